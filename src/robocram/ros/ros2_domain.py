"""A ROS 2 domain of one's own: the first ``ROS_DOMAIN_ID`` no other process on the machine holds.

ROS 2 nodes on one domain find each other; tests, benchmarks and demos that run at once
on one machine must not. ``with free_domain() as domain_id:`` holds a lock file per
domain (``fcntl``, released when the process ends, even by a crash) and yields the
first free one, in order: no random choice.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

from robocram.ros.errors import RosNodeError

DOMAINS = range(1, 102)  # 0 is everyone's default: never taken
LOCKS = Path(tempfile.gettempdir()) / "robocram-ros2-domains"


@contextlib.contextmanager
def free_domain() -> Iterator[int]:
    """Hold the first ROS 2 domain no other ``free_domain`` on this machine holds."""
    LOCKS.mkdir(exist_ok=True)
    for domain in DOMAINS:
        handle = os.open(LOCKS / f"{domain}.lock", os.O_CREAT | os.O_RDWR, 0o666)
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(handle)
            continue
        try:
            yield domain
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)
            os.close(handle)
        return
    raise RosNodeError(f"every ROS 2 domain {DOMAINS.start}..{DOMAINS.stop - 1} is held here")

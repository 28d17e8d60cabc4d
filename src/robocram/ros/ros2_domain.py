"""A ROS 2 domain of one's own: a ``ROS_DOMAIN_ID`` no other process on the machine holds.

ROS 2 nodes on one domain find each other; tests, benchmarks and demos that run at once
on one machine must not. ``with free_domain() as domain_id:`` holds a lock file per
domain (``fcntl``, released when the process ends, even by a crash) and yields the free
domain used least recently (the oldest lock file), so a domain whose last nodes may still
linger in discovery is not taken again at once. No random choice.
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
    """Hold the least recently used ROS 2 domain no other ``free_domain`` here holds."""
    LOCKS.mkdir(exist_ok=True)
    for domain in sorted(DOMAINS, key=_last_used):
        path = LOCKS / f"{domain}.lock"
        handle = os.open(path, os.O_CREAT | os.O_RDWR, 0o666)
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(handle)
            continue
        os.utime(path)
        try:
            yield domain
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)
            os.close(handle)
        return
    raise RosNodeError(f"every ROS 2 domain {DOMAINS.start}..{DOMAINS.stop - 1} is held here")


def _last_used(domain: int) -> tuple[float, int]:
    """When ``domain`` was last taken (its lock file's time; never: 0), then its number."""
    try:
        return (os.stat(LOCKS / f"{domain}.lock").st_mtime, domain)
    except FileNotFoundError:
        return (0.0, domain)

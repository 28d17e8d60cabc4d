"""Start and stop a ROS master on a free port, by the PIDs we started, for tests and demos.

``with Roscore() as core: core.uri`` runs ``roscore -p PORT`` in its own process group
and, on leaving, stops exactly that group (roscore, rosmaster, rosout), waiting for it.
"""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import tempfile
import time
import xmlrpc.client
from pathlib import Path
from types import TracebackType
from typing import Any

from robocram.ros.errors import RosNodeError

START_TIMEOUT = 30.0  # [s]
STOP_TIMEOUT = 10.0  # [s]


def free_port() -> int:
    """A TCP port nobody listens on right now."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Roscore:
    """A ``roscore`` process on a free port (``uri``); a context manager."""

    def __init__(self, port: int | None = None) -> None:
        self.port = port or free_port()
        self.uri = f"http://127.0.0.1:{self.port}"
        self.process: subprocess.Popen[bytes] | None = None
        self._home = tempfile.TemporaryDirectory(prefix="robocram-ros-")

    def start(self) -> Roscore:
        """Start the master and wait until it answers."""
        env = dict(os.environ, ROS_MASTER_URI=self.uri, ROS_HOME=self._home.name)
        self.process = subprocess.Popen(
            ["roscore", "-p", str(self.port)],
            env=env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            start_new_session=True,
        )
        deadline = time.monotonic() + START_TIMEOUT
        while not self.running():
            if self.process.poll() is not None or time.monotonic() > deadline:
                self.stop()
                raise RosNodeError(
                    f"roscore -p {self.port} did not come up; is ros-core installed?"
                )
            time.sleep(0.1)
        return self

    def running(self) -> bool:
        """Whether the master answers."""
        try:
            answer: Any = xmlrpc.client.ServerProxy(self.uri).getPid("/robocram")
        except OSError:
            return False
        return bool(answer[0] == 1)

    def stop(self) -> None:
        """Stop roscore and its children (its process group) and wait for them."""
        process, self.process = self.process, None
        if process is not None and process.poll() is None:
            os.killpg(process.pid, signal.SIGINT)
            try:
                process.wait(STOP_TIMEOUT)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
        if process is not None:
            _kill_group_leftovers(process.pid)
        self._home.cleanup()

    @property
    def home(self) -> Path:
        """ROS_HOME of this master (its logs)."""
        return Path(self._home.name)

    def __enter__(self) -> Roscore:
        return self.start()

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.stop()


def _kill_group_leftovers(group: int) -> None:
    """SIGKILL what is left of the process group we started (rosmaster, rosout)."""
    try:
        os.killpg(group, signal.SIGKILL)
    except ProcessLookupError:
        return

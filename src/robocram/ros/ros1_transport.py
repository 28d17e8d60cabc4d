"""The ROS 1 transport: our rospy node in a child process (``node_process.py``).

``Ros1Transport.open(config)`` first asks the master (``RosMasterUnreachable`` within
``master_timeout``), then starts the child, a fresh interpreter running only
``ros1_node.child_main``.
"""

from __future__ import annotations

import contextlib
import http.client
import os
import sys
import time
import xmlrpc.client
from collections.abc import Iterator

from robocram.ros.errors import RosMasterUnreachable
from robocram.ros.node_process import NodeProcessTransport

MASTER_RETRY = 0.2  # [s] between asking an absent master again
CHILD_CODE = "from robocram.ros.ros1_node import child_main; child_main()"


def wait_for_master(uri: str, timeout: float) -> None:
    """Return once the ROS master at ``uri`` answers; else RosMasterUnreachable in ``timeout``.

    rospy's own start-up waits for a master forever; asking it first makes the error quick.
    """
    deadline = time.monotonic() + timeout
    last = "no answer"
    while True:
        remaining = deadline - time.monotonic()
        try:
            with _timeout_proxy(uri, max(0.05, min(1.0, remaining))) as master:
                master.getPid("/robocram_probe")
            return
        except (OSError, xmlrpc.client.Error) as err:
            last = f"{type(err).__name__}: {err}"
        if time.monotonic() + MASTER_RETRY > deadline:
            raise RosMasterUnreachable(
                f"no ROS master answered at {uri} within {timeout} s ({last}); start roscore "
                "there (or fix master_uri / $ROS_MASTER_URI), or give ros_robot a longer "
                "master_timeout"
            )
        time.sleep(MASTER_RETRY)


@contextlib.contextmanager
def _timeout_proxy(uri: str, timeout: float) -> Iterator[xmlrpc.client.ServerProxy]:
    """An XML-RPC proxy whose socket gives up after ``timeout`` [s]."""
    transport = _TimeoutTransport(timeout)
    with xmlrpc.client.ServerProxy(uri, transport=transport) as proxy:
        yield proxy


class _TimeoutTransport(xmlrpc.client.Transport):
    def __init__(self, timeout: float) -> None:
        super().__init__()
        self._timeout = timeout

    def make_connection(self, host: tuple[str, dict[str, str]] | str) -> http.client.HTTPConnection:
        connection = super().make_connection(host)
        connection.timeout = self._timeout
        return connection


class Ros1Transport(NodeProcessTransport):
    """rospy + actionlib + tf2 in a child process; see :class:`~robocram.ros.Transport`."""

    def _launch(self) -> tuple[list[str], dict[str, str]]:
        wait_for_master(self.config.master_uri, self.config.master_timeout)
        # A fresh interpreter running only our node: multiprocessing's spawn would import
        # the caller's main script again (the whole plan side) before the node starts.
        env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
        return [sys.executable, "-c", CHILD_CODE], env

    def _joining(self) -> str:
        return f"the master {self.config.master_uri} (is roscore running there?)"

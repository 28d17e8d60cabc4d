"""Who hears of executed trajectories: traces, viewers, tests, without a global.

Projection and ROS call :func:`report_executed` once per trajectory they executed (or
began to: a stopped one is reported as far as it got). Listeners registered with
``with trajectory_listener(fn):`` in the current context get each one; outside any such
block nobody listens and reporting costs nothing. The registration is a ContextVar, so
threads and asyncio tasks started inside the block inherit it, and two traced runs in
two threads do not hear each other.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from contextvars import ContextVar

from robocram.motion.joint_trajectory import JointTrajectory

TrajectoryListener = Callable[[JointTrajectory], None]

_LISTENERS: ContextVar[tuple[TrajectoryListener, ...]] = ContextVar(
    "robocram_trajectory_listeners", default=()
)


@contextlib.contextmanager
def trajectory_listener(listener: TrajectoryListener) -> Iterator[None]:
    """Inside the block, ``listener`` is called with every executed trajectory."""
    token = _LISTENERS.set((*_LISTENERS.get(), listener))
    try:
        yield
    finally:
        _LISTENERS.reset(token)


def report_executed(trajectory: JointTrajectory) -> None:
    """Tell the current listeners that ``trajectory`` was executed."""
    for listener in _LISTENERS.get():
        listener(trajectory)

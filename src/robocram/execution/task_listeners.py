"""Observers of running plans: listeners told when tasks start, finish or perform.

A tracer, a live viewer or a progress bar registers a :class:`TaskListener` for a block
with ``with listening(listener):``. The listeners live in a ContextVar, so they follow the
plan into the threads of ``par`` and friends and never leak into unrelated plans. The
executive only calls the hooks; what a listener does with them (SQL, websockets) stays in
the layers above. A listener's hooks run in the plan's thread and must be quick and
thread-safe; an exception from a hook propagates into the plan, like any bug.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from robocram.execution.errors import ExecutionUsageError
from robocram.execution.task import TASK_OBSERVERS, Task


class TaskListener:
    """Hooks called by the executive; override the ones you need (the rest do nothing)."""

    def task_started(self, task: Task) -> None:
        """``task`` has begun running (status and start time are set)."""

    def task_finished(self, task: Task) -> None:
        """``task`` has ended (status, end time, result or failure are set)."""

    def performing(self, task: Task, designator: Any) -> None:
        """``task`` (already started) is the PERFORM of ``designator``."""


@contextmanager
def listening(listener: TaskListener) -> Iterator[TaskListener]:
    """Tell ``listener`` about every task started inside the block (also in its threads)."""
    if not isinstance(listener, TaskListener):
        raise ExecutionUsageError(f"listening() needs a TaskListener, got {listener!r}")
    token = TASK_OBSERVERS.set((*TASK_OBSERVERS.get(), listener))
    try:
        yield listener
    finally:
        TASK_OBSERVERS.reset(token)


def task_listeners() -> tuple[TaskListener, ...]:
    """The listeners registered in the current context, outermost first."""
    return tuple(o for o in TASK_OBSERVERS.get() if isinstance(o, TaskListener))


def notify_performing(task: Task, designator: object) -> None:
    """Call ``performing`` on every current listener."""
    for listener in task_listeners():
        listener.performing(task, designator)

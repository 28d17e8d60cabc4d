"""Observers of running plans: listeners told when tasks start, finish or perform.

A tracer, a live viewer or a progress bar registers a :class:`TaskListener` for a block
with ``with listening(listener):``. The listeners live in a ContextVar, so they follow the
plan into the threads of ``par`` and friends and never leak into unrelated plans. The
executive only calls the hooks; what a listener does with them (SQL, websockets) stays in
the layers above. A listener's hooks run in the plan's thread and must be quick and
thread-safe; an exception from a hook propagates into the plan, like any bug.
"""

from __future__ import annotations

import contextvars
from collections.abc import Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from robocram.execution.task import Task

_LISTENERS: contextvars.ContextVar[tuple[TaskListener, ...]] = contextvars.ContextVar(
    "robocram_task_listeners", default=()
)


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
        raise TypeError(f"listening() needs a TaskListener, got {listener!r}")
    token = _LISTENERS.set((*_LISTENERS.get(), listener))
    try:
        yield listener
    finally:
        _LISTENERS.reset(token)


def task_listeners() -> tuple[TaskListener, ...]:
    """The listeners registered in the current context, outermost first."""
    return _LISTENERS.get()


def notify_started(task: Task) -> None:
    """Call ``task_started`` on every current listener."""
    for listener in _LISTENERS.get():
        listener.task_started(task)


def notify_finished(task: Task) -> None:
    """Call ``task_finished`` on every current listener."""
    for listener in _LISTENERS.get():
        listener.task_finished(task)


def notify_performing(task: Task, designator: Any) -> None:
    """Call ``performing`` on every current listener."""
    for listener in _LISTENERS.get():
        listener.performing(task, designator)

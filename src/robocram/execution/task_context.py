"""The running task, bound dynamically per thread of control (a ContextVar).

Plan forms bind the task they create; threads started by ``par`` and friends copy the
context, so ``current_task()`` in a child thread is the child task. The stop points
(``checkpoint``, ``sleep``, ``wait_until``) live here because they act on that task.
"""

from __future__ import annotations

import contextvars
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager, nullcontext
from typing import Any

from robocram.execution.errors import ExecutionArgumentError
from robocram.execution.failures import NotInTopLevel
from robocram.execution.task import Task, TaskStatus, TaskStopped
from robocram.logic.limits import checking_stop

_CURRENT_TASK: contextvars.ContextVar[Task | None] = contextvars.ContextVar(
    "robocram_current_task", default=None
)


def current_task() -> Task | None:
    """Return the task running in this context, or None outside any top level."""
    return _CURRENT_TASK.get()


def require_task(form: str) -> Task:
    """Return the running task, or raise NotInTopLevel naming the plan ``form``."""
    task = _CURRENT_TASK.get()
    if task is None:
        raise NotInTopLevel(form)
    return task


@contextmanager
def binding_task(task: Task) -> Iterator[Task]:
    """Make ``task`` the current task inside the block (queries in it check its stop)."""
    token = _CURRENT_TASK.set(task)
    try:
        with checking_stop(checkpoint):
            yield task
    finally:
        _CURRENT_TASK.reset(token)


def checkpoint() -> None:
    """Stop point: raise TaskStopped if the current task was stopped; no-op outside plans."""
    task = _CURRENT_TASK.get()
    if task is not None:
        task.check_stop()


def wait_until(
    cond: threading.Condition, ready: Callable[[], bool], timeout: float | None = None
) -> bool:
    """Wait on ``cond`` until ``ready()`` holds; False on timeout [s]; a stop point.

    ``ready`` is called with ``cond`` held; whoever makes it true must notify ``cond``.
    The caller must not hold ``cond``.
    """
    task = _CURRENT_TASK.get()
    deadline = None if timeout is None else time.monotonic() + timeout
    with task.watching(cond) if task is not None else nullcontext(), cond:
        while task is None or not task.stop_requested:
            if ready():
                return True
            remaining = None if deadline is None else deadline - time.monotonic()
            if remaining is not None and remaining <= 0:
                return False
            cond.wait(remaining)
    raise TaskStopped(task)


def sleep(seconds: float) -> None:
    """Sleep ``seconds`` [s], waking early to unwind if the current task is stopped."""
    if seconds < 0:
        raise ExecutionArgumentError(f"sleep needs a non-negative duration [s], got {seconds}")
    checkpoint()
    wait_until(threading.Condition(), lambda: False, seconds)
    checkpoint()


@contextmanager
def sub_task(name: str, tags: frozenset[str] = frozenset()) -> Iterator[Task]:
    """Run the block as a child task of the current task, in this thread.

    The block may set ``task.result``; on leaving, the task is marked succeeded, failed
    (failure kept, then re-raised) or evaporated (on TaskStopped, re-raised).
    """
    parent = require_task(f"sub_task({name!r})")
    task = Task(name, parent, tags)
    task.begin()
    try:
        with binding_task(task):
            task.check_stop()
            yield task
    except TaskStopped:
        task.finish(TaskStatus.EVAPORATED)
        raise
    except BaseException as error:
        task.finish(TaskStatus.FAILED, failure=error)
        raise
    task.finish(TaskStatus.SUCCEEDED, result=task.result)


def start_in_thread(
    task: Task, fn: Callable[[], Any], done: Callable[[Task], None]
) -> threading.Thread:
    """Run ``fn`` as ``task`` in a new thread that inherits this context; returns the thread.

    ``done(task)`` is called in that thread once the outcome is recorded.
    """
    context = contextvars.copy_context()

    def main() -> None:
        try:
            with binding_task(task):
                task.run(fn)
        finally:
            done(task)

    thread = threading.Thread(target=context.run, args=(main,), name=f"robocram:{task.path}")
    thread.start()
    return thread

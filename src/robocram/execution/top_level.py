"""Top levels: run a plan as the root task of a task tree and join it.

Three forms, one object. ``top_level(plan, *args)`` runs and returns the value (or
raises the failure); ``with top_level(name="demo") as tl:`` runs the block as the root
task; ``@top_level(name="demo")`` or a bare ``@top_level`` makes every call a top-level
run. ``tl.tree`` is the TaskTree of the last run, also after a failure;
``run_top_level(plan)`` returns ``(value, tree)``. Inside another top level, a top level
becomes a child task.

A bare ``@top_level`` and ``top_level(plan)`` are the same call; they are told apart by
where the call comes from: a decorator is called from the lines of the decorated
function's own definition (its decorators and ``def`` header), a plan run from anywhere
else.
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Callable
from types import TracebackType
from typing import Any, TypeVar, overload

from robocram.execution.par import raise_failure_of
from robocram.execution.task import Task, TaskStatus, TaskStopped
from robocram.execution.task_context import (
    _CURRENT_TASK,
    binding_task,
    checkpoint,
    current_task,
)
from robocram.execution.task_tree import TaskTree
from robocram.logic.limits import checking_stop

T = TypeVar("T")


class TopLevel:
    """A top-level runner; also a context manager and a decorator."""

    def __init__(self, name: str = "top-level") -> None:
        self.name = name
        self._task: Task | None = None
        self._token: Any = None
        self._stop_check: Any = None

    @property
    def task(self) -> Task:
        """The root task of the current or last run."""
        if self._task is None:
            raise RuntimeError(f"top level {self.name!r} has not run yet; no task")
        return self._task

    @property
    def tree(self) -> TaskTree:
        """The task tree of the current or last run."""
        return TaskTree(self.task)

    def stop(self) -> None:
        """Ask the running plan to stop (from another thread)."""
        self.task.stop()

    def _new_root(self) -> Task:
        return Task(self.name, current_task())

    def run(self, fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
        """Run ``fn(*args, **kwargs)`` as the root task in this thread; join; return or raise."""
        task = self._task = self._new_root()
        with binding_task(task):
            task.run(lambda: fn(*args, **kwargs))
        if task.status is TaskStatus.FAILED:
            raise_failure_of(task)
        if task.status is TaskStatus.EVAPORATED:
            raise TaskStopped(task)
        return task.result

    def __enter__(self) -> TopLevel:
        if self._token is not None:
            raise RuntimeError(f"top level {self.name!r} is already running; make a new one")
        task = self._task = self._new_root()
        task.begin()
        self._token = _CURRENT_TASK.set(task)
        self._stop_check = checking_stop(checkpoint)  # a looping query stops with the task
        self._stop_check.__enter__()
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self._stop_check.__exit__(None, None, None)
        _CURRENT_TASK.reset(self._token)
        self._token = None
        task = self.task
        if exc is None:
            task.finish(TaskStatus.SUCCEEDED, result=task.result)
        elif isinstance(exc, TaskStopped):
            task.finish(TaskStatus.EVAPORATED)
        else:
            task.finish(TaskStatus.FAILED, failure=exc)

    def __call__(self, fn: Callable[..., T]) -> Callable[..., T]:
        """Decorate ``fn`` so that each call is a top-level run (the last run's tree kept)."""

        @functools.wraps(fn)
        def wrapper(*args: Any, **kwargs: Any) -> T:
            return self.run(fn, *args, **kwargs)

        return wrapper


@overload
def top_level(fn: None = None, *, name: str | None = None) -> TopLevel: ...
@overload
def top_level(fn: Callable[..., T], *args: Any, name: str | None = None, **kwargs: Any) -> T: ...
def top_level(
    fn: Callable[..., Any] | None = None, *args: Any, name: str | None = None, **kwargs: Any
) -> Any:
    """Run ``fn`` as a top level and return its value; without ``fn``, return a TopLevel."""
    if fn is None:
        if args or kwargs:
            raise TypeError("top_level() got plan arguments but no plan; pass the plan first")
        return TopLevel(name or "top-level")
    runner = TopLevel(name or _name_of(fn))
    if not args and not kwargs and _decorating(fn, sys._getframe(1).f_lineno):
        return runner(fn)
    return runner.run(fn, *args, **kwargs)


def _decorating(fn: Callable[..., Any], caller_line: int) -> bool:
    """Whether ``fn`` is being decorated: called from its own decorator or ``def`` lines.

    A function's code starts at its first decorator; its body starts after the ``def``
    header, so a call from a line in between comes from a decorator of this very function.
    """
    code = getattr(fn, "__code__", None)
    if code is None:
        return False
    first = code.co_firstlineno
    body = min((line for _, _, line in code.co_lines() if line and line > first), default=first)
    return first <= caller_line < body


def run_top_level(
    fn: Callable[..., T], *args: Any, name: str | None = None, **kwargs: Any
) -> tuple[T, TaskTree]:
    """Run ``fn`` as a top level; return its value and the task tree."""
    runner = TopLevel(name or _name_of(fn))
    return runner.run(fn, *args, **kwargs), runner.tree


def _name_of(fn: Callable[..., Any]) -> str:
    name = getattr(fn, "__name__", "")
    return name if name.isidentifier() else "top-level"

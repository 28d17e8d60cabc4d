"""Top levels: run a plan as the root task of a task tree and join it.

Two names. ``run_top_level(plan, *args)`` runs now and returns the value (or raises the
failure). ``top_level`` never runs a plan: ``@top_level``, ``@top_level()`` or
``@top_level(name="demo")`` decorate (every call of the plan is then a top-level run), and
``with top_level(name="demo") as tl:`` runs a block as the root task. ``tl.tree`` is the
TaskTree of the last run, also after a failure. Inside another top level, a top level
becomes a child task.

A bare ``@top_level`` calls ``top_level(plan)`` while the ``def`` statement runs: the
caller is the scope the function is defined in, and the function's name is not bound to
it yet. Any other ``top_level(plan)``, with a lambda, a function already bound (from
another module, on any line), or plan arguments, could mean either and is a TypeError
naming both forms.
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Callable
from types import FrameType, FunctionType, TracebackType
from typing import Any, TypeVar, overload

from robocram.execution.errors import ExecutionStateError, ExecutionUsageError
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
            raise ExecutionStateError(f"top level {self.name!r} has not run yet; no task")
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

    def run(self, fn: Callable[..., T], *args: object, **kwargs: object) -> T:
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
            raise ExecutionStateError(f"top level {self.name!r} is already running; make a new one")
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
        def wrapper(*args: object, **kwargs: object) -> T:
            return self.run(fn, *args, **kwargs)

        return wrapper


AMBIGUOUS = (
    "top_level({plan}) could decorate or run: decorate with @top_level above the def (or "
    "@top_level(name=...)); run a plan now with run_top_level(plan, *args)"
)


@overload
def top_level(fn: None = None, *, name: str | None = None) -> TopLevel: ...
@overload
def top_level(fn: Callable[..., T], *, name: str | None = None) -> Callable[..., T]: ...
def top_level(fn: Callable[..., Any] | None = None, *args: object, name: str | None = None) -> Any:
    """Decorate ``fn`` as a top-level plan; without ``fn``, a TopLevel (decorator, ``with``).

    Raises:
        TypeError: ``fn`` is not being decorated (see the module docstring), or plan
            arguments were given; the message names ``@top_level`` and ``run_top_level``.
    """
    if fn is None:
        if args:
            raise ExecutionUsageError(
                "top_level() got plan arguments but no plan; use run_top_level"
            )
        return TopLevel(name or "top-level")
    if args or not _decorating(fn, sys._getframe(1)):
        raise ExecutionUsageError(AMBIGUOUS.format(plan=getattr(fn, "__name__", repr(fn))))
    return TopLevel(name or _name_of(fn))(fn)


def _decorating(fn: Callable[..., object], caller: FrameType) -> bool:
    """Whether ``fn``'s ``def`` statement is running in ``caller``, not yet bound.

    A decorator is called by the frame that executes the ``def``: the scope named by the
    function's qualified name (the module, a class body or an enclosing function), before
    the name is bound to the function. Nothing else meets both.
    """
    if not isinstance(fn, FunctionType) or fn.__name__ == "<lambda>":
        return False
    parent = fn.__qualname__.rpartition(".")[0]
    scope = parent.removesuffix(".<locals>").rpartition(".")[2] or "<module>"
    if caller.f_code.co_name != scope:
        return False
    if not parent and caller.f_globals.get("__name__") != fn.__module__:
        return False
    return caller.f_locals.get(fn.__name__) is not fn


def run_top_level(
    fn: Callable[..., T], *args: object, name: str | None = None, **kwargs: object
) -> T:
    """Run ``fn(*args, **kwargs)`` as a top level now; return its value or raise its failure.

    For the task tree as well, run a :class:`TopLevel` and read its ``tree``.
    """
    return TopLevel(name or _name_of(fn)).run(fn, *args, **kwargs)


def _name_of(fn: Callable[..., object]) -> str:
    name = getattr(fn, "__name__", "")
    return name if name.isidentifier() else "top-level"

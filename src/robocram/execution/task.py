"""Tasks: the nodes of a running plan, each with a status, times and an outcome.

Stopping and suspending are cooperative. ``stop()`` and ``suspend()`` only set flags and
wake the task's waits; the task notices at its next stop point (``check_stop``, a sleep,
a fluent wait, a PERFORM) and unwinds with :class:`TaskStopped` or blocks until resumed.
A request on a task applies to all its descendants. A task tells the observers in its
context when it starts and ends (``with listening(...)``, :mod:`task_listeners`).
"""

from __future__ import annotations

import contextvars
import enum
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, Protocol

from robocram.execution.released_frames import release_frames

WHOLE_FAILURES = 4  # a task tree's latest failures keep their frames' locals


class TaskObserver(Protocol):
    """Told when a task starts and ends (a :class:`TaskListener` is one)."""

    def task_started(self, task: Task) -> None: ...
    def task_finished(self, task: Task) -> None: ...


TASK_OBSERVERS: contextvars.ContextVar[tuple[TaskObserver, ...]] = contextvars.ContextVar(
    "robocram_task_listeners", default=()
)


class TaskStatus(enum.Enum):
    """Lifecycle of a task (CRAM's names)."""

    CREATED = "created"
    RUNNING = "running"
    SUSPENDED = "suspended"
    SUCCEEDED = "succeeded"
    FAILED = "failed"
    EVAPORATED = "evaporated"

    @property
    def done(self) -> bool:
        """Whether the task has finished, one way or another."""
        return self in (TaskStatus.SUCCEEDED, TaskStatus.FAILED, TaskStatus.EVAPORATED)


class TaskStopped(BaseException):  # noqa: N818 - reads as what happened
    """Unwinds a task that was asked to stop (CRAM: the task evaporates).

    Derives from BaseException, like KeyboardInterrupt, so that ``except Exception`` in
    user code and failure handlers never catch it: stopping is not a failure to recover.
    """

    def __init__(self, task: Task) -> None:
        super().__init__(f"task {task.path} was stopped")
        self.task = task


class Task:
    """One node of the task tree; thread-safe; created by plan forms, not by users."""

    def __init__(self, name: str, parent: Task | None = None, tags: frozenset[str] = frozenset()):
        self.parent = parent
        self.tags = tags
        self.children: list[Task] = []
        self.status = TaskStatus.CREATED
        self.start_time: float | None = None  # [s] since the epoch
        self.end_time: float | None = None  # [s] since the epoch
        self.result: Any = None
        self.failure: BaseException | None = None
        self._lock = threading.Lock()
        self._stop = False
        self._suspended = False
        self._wakers: list[threading.Condition] = []
        self._whole: list[BaseException] = []  # the root's latest failures, frames intact
        self.name = parent._add_child(self, name) if parent is not None else name

    def _keep_whole(self, failure: BaseException) -> None:
        """Keep ``failure`` whole among its tree's latest :data:`WHOLE_FAILURES`; an older
        one loses its frames' locals (:func:`release_frames`).

        The tree outlives its failures' frames, and a long activity recovers from hundreds:
        kept whole, they held every failed motion's collision scene (gigabytes). The latest
        stay whole, so that a debugger's post-mortem of a plan's failure sees its locals.
        """
        root = self
        while root.parent is not None:
            root = root.parent
        with root._lock:
            kept = [f for f in root._whole if f is not failure]
            kept.append(failure)
            old, root._whole = kept[:-WHOLE_FAILURES], kept[-WHOLE_FAILURES:]
        for done in old:
            release_frames(done)

    def _add_child(self, child: Task, name: str) -> str:
        with self._lock:
            taken = {c.name for c in self.children}
            unique, n = name, 1
            while unique in taken:
                n += 1
                unique = f"{name}#{n}"
            self.children.append(child)
            return unique

    def __repr__(self) -> str:
        return f"Task({self.path!r}, {self.status.value})"

    @property
    def path(self) -> str:
        """Slash-separated names from the root, e.g. ``"plan/par/fetch"``."""
        return self.name if self.parent is None else f"{self.parent.path}/{self.name}"

    @property
    def root(self) -> Task:
        """The top-level task this task belongs to."""
        return self if self.parent is None else self.parent.root

    def ancestors(self) -> Iterator[Task]:
        """This task, its parent, and so on up to the root."""
        task: Task | None = self
        while task is not None:
            yield task
            task = task.parent

    def descendants(self) -> Iterator[Task]:
        """This task and every task below it, depth first."""
        yield self
        with self._lock:
            children = list(self.children)
        for child in children:
            yield from child.descendants()

    @property
    def duration(self) -> float | None:
        """Run time [s] so far or in total; None before the start."""
        if self.start_time is None:
            return None
        return (self.end_time or time.time()) - self.start_time

    @property
    def stop_requested(self) -> bool:
        """Whether this task or an ancestor has been asked to stop."""
        return self._up_the_tree("_stop")

    @property
    def suspend_requested(self) -> bool:
        """Whether this task or an ancestor has been asked to suspend."""
        return self._up_the_tree("_suspended")

    def _up_the_tree(self, flag: str) -> bool:
        """Whether ``flag`` is set on this task or an ancestor (a plain loop: a plan passes
        hundreds of stop points)."""
        task: Task | None = self
        while task is not None:
            if getattr(task, flag):
                return True
            task = task.parent
        return False

    def stop(self) -> None:
        """Ask this task and its descendants to stop at their next stop point."""
        with self._lock:
            self._stop = True
        self._wake_subtree()

    def suspend(self) -> None:
        """Ask this task and its descendants to pause at their next stop point."""
        with self._lock:
            self._suspended = True

    def resume(self) -> None:
        """Let a suspended task (and its descendants) continue."""
        with self._lock:
            self._suspended = False
        self._wake_subtree()

    def _wake_subtree(self) -> None:
        wakers = []
        for task in self.descendants():
            with task._lock:
                wakers.extend(task._wakers)
        for cond in wakers:
            with cond:
                cond.notify_all()

    @contextmanager
    def watching(self, cond: threading.Condition) -> Iterator[None]:
        """Register ``cond`` so that stop/resume requests wake a wait on it."""
        with self._lock:
            self._wakers.append(cond)
        try:
            yield
        finally:
            with self._lock:
                self._wakers.remove(cond)

    def check_stop(self) -> None:
        """Stop point: raise TaskStopped if asked to stop; block while suspended.

        One walk up the tree for both flags: plans pass hundreds of stop points per run.
        """
        task: Task | None = self
        suspended = False
        while task is not None:
            if task._stop:
                raise TaskStopped(self)
            suspended = suspended or task._suspended
            task = task.parent
        if suspended:
            self._wait_resumed()

    def _wait_resumed(self) -> None:
        cond = threading.Condition()
        self.status = TaskStatus.SUSPENDED
        with self.watching(cond), cond:
            while self.suspend_requested and not self.stop_requested:
                cond.wait()
        self.status = TaskStatus.RUNNING
        if self.stop_requested:
            raise TaskStopped(self)

    def run(self, fn: Callable[[], Any]) -> None:
        """Run ``fn`` as this task in the calling thread and record the outcome; never raises.

        The caller (a plan form) reads ``status``, ``result`` and ``failure`` afterwards.
        """
        self.begin()
        try:
            self.check_stop()
            result = fn()
        except TaskStopped:
            self.finish(TaskStatus.EVAPORATED)
        except BaseException as error:  # recorded here, re-raised by the parent form
            self.finish(TaskStatus.FAILED, failure=error)
        else:
            self.finish(TaskStatus.SUCCEEDED, result=result)

    def begin(self) -> None:
        """Mark the task running from now."""
        self.start_time = time.time()
        self.status = TaskStatus.RUNNING
        for observer in TASK_OBSERVERS.get():
            observer.task_started(self)

    def finish(
        self, status: TaskStatus, result: object = None, failure: BaseException | None = None
    ) -> None:
        """Record the outcome and end time."""
        if failure is not None:
            self._keep_whole(failure)
        self.result, self.failure = result, failure
        self.end_time = time.time()
        self.status = status
        for observer in TASK_OBSERVERS.get():
            observer.task_finished(self)

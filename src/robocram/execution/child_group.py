"""Child tasks run in threads under one plan form, reported as they finish.

``par``, ``pursue``, ``try_all`` and ``partial_order`` differ only in what they do when a
child finishes; the threads, the finish queue and the final join are shared here.
Every group is joined before its form returns or raises, so no thread outlives a form.
"""

from __future__ import annotations

import queue
import threading
from collections.abc import Callable, Iterable, Iterator, Sequence

from robocram.execution.errors import ExecutionUsageError
from robocram.execution.task import Task
from robocram.execution.task_context import start_in_thread

Step = Callable[[], object] | tuple[str, Callable[[], object]]


def named_steps(form: str, steps: Iterable[Step]) -> list[tuple[str, Callable[[], object]]]:
    """Normalise thunks and ``(name, thunk)`` pairs to pairs; name lambdas ``form[i]``."""
    named: list[tuple[str, Callable[[], object]]] = []
    for i, step in enumerate(steps):
        if isinstance(step, tuple) and len(step) == 2 and isinstance(step[0], str):
            name, fn = step
        else:
            fn = step
            name = getattr(fn, "__name__", "")
            name = name if name.isidentifier() else f"{form}[{i}]"
        if not callable(fn):
            raise ExecutionUsageError(
                f"{form} step {i} is {fn!r}, not a callable; "
                f"wrap the call in a lambda: {form}(lambda: f(...), ...)"
            )
        named.append((name, fn))
    return named


class ChildGroup:
    """Threads running the steps of one form as child tasks of ``parent``."""

    def __init__(self, parent: Task, steps: Sequence[tuple[str, Callable[[], object]]]) -> None:
        self.tasks = [Task(name, parent) for name, _ in steps]
        self._fns = [fn for _, fn in steps]
        self._finished: queue.SimpleQueue[Task] = queue.SimpleQueue()
        self._threads: list[threading.Thread] = []

    def __enter__(self) -> ChildGroup:
        for task, fn in zip(self.tasks, self._fns, strict=True):
            self._threads.append(start_in_thread(task, fn, self._finished.put))
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop_all()
        for thread in self._threads:
            thread.join()

    def finished(self) -> Iterator[Task]:
        """Yield each child task as it finishes, in finishing order."""
        for _ in self._threads:
            yield self._finished.get()

    def stop_all(self) -> None:
        """Ask every unfinished child to stop."""
        for task in self.tasks:
            if not task.status.done:
                task.stop()

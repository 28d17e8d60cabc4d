"""A task and its subtree frozen at one moment: what every view of a task tree reads.

Display is kept apart from the model: text (``execution/tree_text.py``), JSON, traces and
the viewer read one consistent :class:`TaskSnapshot`, never the live tasks.
"""

from __future__ import annotations

import reprlib
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from robocram.execution.failures.failure_line import failure_line
from robocram.execution.task import Task, TaskStatus

_repr = reprlib.Repr()
_repr.maxstring = 60
_repr.maxother = 400
_RESULT_WIDTH = 72  # [characters] of a result shown in the tree


def _result_text(value: object) -> str:
    """A bounded repr that keeps the start of the value (its type and first fields)."""
    text = _repr.repr(value)
    return text if len(text) <= _RESULT_WIDTH else text[: _RESULT_WIDTH - 1] + "…"


STATUS_MARKS: dict[TaskStatus, str] = {  # one glyph per status, for every view of a tree
    TaskStatus.CREATED: "·",
    TaskStatus.RUNNING: "…",
    TaskStatus.SUSPENDED: "‖",
    TaskStatus.SUCCEEDED: "✓",
    TaskStatus.FAILED: "✗",
    TaskStatus.EVAPORATED: "○",
}


@dataclass(frozen=True)
class TaskSnapshot:
    """A task and its subtree as they were at one moment."""

    name: str
    path: str
    status: TaskStatus
    start_time: float | None  # [s] since the epoch
    end_time: float | None  # [s] since the epoch
    result: str | None  # repr, shortened
    failure_type: str | None
    failure_message: str | None
    failure_source: str | None  # path of the task where the failure was first raised
    tags: tuple[str, ...]
    children: tuple[TaskSnapshot, ...]

    @classmethod
    def of(cls, task: Task) -> TaskSnapshot:
        """Snapshot ``task`` and its descendants."""
        failure = task.failure
        children = tuple(cls.of(child) for child in list(task.children))
        source = task.path if failure is not None else None
        for live, snap in zip(list(task.children), children, strict=False):
            if failure is not None and live.failure is failure:
                source = snap.failure_source
        return cls(
            name=task.name,
            path=task.path,
            status=task.status,
            start_time=task.start_time,
            end_time=task.end_time,
            result=_result_text(task.result) if task.status is TaskStatus.SUCCEEDED else None,
            failure_type=type(failure).__name__ if failure is not None else None,
            failure_message=str(failure) if failure is not None else None,
            failure_source=source,
            tags=tuple(sorted(task.tags)),
            children=children,
        )

    @property
    def duration(self) -> float | None:
        """Run time [s]; None unless started and finished."""
        if self.start_time is None or self.end_time is None:
            return None
        return self.end_time - self.start_time

    def walk(self) -> Iterator[TaskSnapshot]:
        """This snapshot and all below it, depth first."""
        yield self
        for child in self.children:
            yield from child.walk()

    def to_json(self) -> dict[str, Any]:
        """A JSON-able dict with the same fields; children nested."""
        return {
            "name": self.name,
            "path": self.path,
            "status": self.status.value,
            "start": self.start_time,
            "end": self.end_time,
            "duration": self.duration,
            "result": self.result,
            "failure": None
            if self.failure_type is None
            else {
                "type": self.failure_type,
                "message": self.failure_message,
                "source": self.failure_source,
            },
            "tags": list(self.tags),
            "children": [child.to_json() for child in self.children],
        }

    def label(self, verbose: bool = True) -> str:
        """One line: mark, name, status, duration [ms], then the value or failure.

        Not ``verbose``, a failure raised here shows as its :func:`failure_line`.
        """
        text = f"{STATUS_MARKS[self.status]} {self.name} {self.status.value}"
        if self.duration is not None:
            text += f" {self.duration * 1000:.1f} ms"
        if self.tags:
            text += " #" + " #".join(self.tags)
        if self.result is not None and self.result != "None":
            text += f" → {self.result}"
        if self.failure_source is not None and self.failure_source != self.path:
            text += f": {self.failure_type} from {self.failure_source[len(self.path) + 1 :]}"
        elif self.failure_type is not None and verbose:
            text += f": {self.failure_type}: {self.failure_message}"
        elif self.failure_type is not None:
            text += f": {failure_line(self.failure_type, self.failure_message)}"
        return text

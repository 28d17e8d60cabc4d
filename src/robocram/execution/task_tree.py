"""The task tree of a top level: its live tasks, snapshots of them, text and JSON views."""

from __future__ import annotations

from typing import Any

from robocram.execution.errors import ExecutionUnknownKey
from robocram.execution.task import Task
from robocram.execution.task_snapshot import TaskSnapshot
from robocram.execution.tree_text import tree_text


class TaskTree:
    """The tasks of one top-level run, rooted at its top-level task."""

    def __init__(self, root: Task) -> None:
        self.root = root

    def snapshot(self) -> TaskSnapshot:
        """Freeze the tree as it is now."""
        return TaskSnapshot.of(self.root)

    def render(self, verbose: bool = False) -> str:
        """The tree as unicode text: recovered tries folded, or (``verbose``) every task."""
        return tree_text(self.snapshot(), verbose)

    def to_json(self) -> dict[str, Any]:
        """The tree as nested JSON-able dicts."""
        return self.snapshot().to_json()

    def tasks(self) -> list[Task]:
        """All live tasks, depth first."""
        return list(self.root.descendants())

    def find(self, path: str) -> Task:
        """The task at ``path`` (e.g. ``"plan/par/fetch"``); KeyError names close paths."""
        tasks = {task.path: task for task in self.root.descendants()}
        if path in tasks:
            return tasks[path]
        near = [p for p in tasks if p.endswith(path.rsplit("/", 1)[-1])][:3]
        raise ExecutionUnknownKey(f"no task at {path!r}; paths ending alike: {near or 'none'}")

    def find_tag(self, tag: str) -> list[Task]:
        """Every task tagged ``tag``, depth first."""
        return [task for task in self.root.descendants() if tag in task.tags]

"""The task tree in the browser: one button per task, children in a folder below it.

A button's label carries the task's status mark, name, status and duration; clicking it
asks the viewer to show the world as it was when that task ended (or now, if running).
The task whose world is on screen is marked (``▶``, blue) as the slider or replay moves.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

import viser

from robocram.execution import STATUS_MARKS, TaskSnapshot, TaskStatus

CURRENT = "▶ "  # put before the label of the task whose world is shown
CURRENT_COLOR = "blue"
COLORS: dict[TaskStatus, Any] = {
    TaskStatus.FAILED: "red",
    TaskStatus.SUCCEEDED: "teal",
    TaskStatus.RUNNING: "yellow",
}


def task_label(task: TaskSnapshot) -> str:
    """Mark, name and status of a task, e.g. ``✓ perform looking succeeded``."""
    return f"{STATUS_MARKS[task.status]} {task.name} {task.status.value}"


def task_hint(task: TaskSnapshot) -> str:
    """The tooltip: duration [ms] and the failure raised here, if any."""
    text = "running" if task.duration is None else f"{task.duration * 1e3:.0f} ms"
    if task.failure_type is not None:
        text += f"; {task.failure_type}: {task.failure_message}"
    return text + "; click to see the world when it ended"


class TaskPanel:
    """Buttons for the tasks of one run, kept in step with the latest tree snapshot."""

    def __init__(self, gui: Any, on_select: Callable[[TaskSnapshot], None]) -> None:
        self.gui = gui
        self.on_select = on_select
        self.folder = gui.add_folder("Task tree")
        self._buttons: dict[str, viser.GuiButtonHandle] = {}
        self._folders: dict[str, Any] = {}
        self._tasks: dict[str, TaskSnapshot] = {}
        self._lock = threading.Lock()
        self.current: str | None = None  # the path of the task whose world is shown

    def highlight(self, path: str | None) -> None:
        """Mark the task at ``path`` (None or an unknown path: none) as the one whose world
        is on screen, and unmark the one before."""
        with self._lock:
            if path == self.current:
                return
            previous, self.current = self.current, path if path in self._buttons else None
            for marked in (previous, self.current):
                if marked is not None:
                    self._dress(self._tasks[marked], self._buttons[marked])

    def _dress(self, task: TaskSnapshot, button: viser.GuiButtonHandle) -> None:
        """Give ``button`` ``task``'s label, colour and hint, marked if it is current."""
        label, color = task_label(task), COLORS.get(task.status)
        if task.path == self.current:
            label, color = CURRENT + label, CURRENT_COLOR
        if button.label != label:
            button.label, button.color, button.hint = label, color, task_hint(task)

    def update(self, tree: TaskSnapshot) -> None:
        """Add buttons for new tasks and relabel changed ones."""
        with self._lock:
            self._update(tree, self.folder)

    def _update(self, task: TaskSnapshot, container: Any) -> None:
        self._tasks[task.path] = task
        button = self._buttons.get(task.path)
        if button is None:
            label, color = task_label(task), COLORS.get(task.status)
            with container:
                button = self.gui.add_button(label, color=color, hint=task_hint(task))
            button.on_click(lambda _event, path=task.path: self.on_select(self._tasks[path]))
            self._buttons[task.path] = button
        self._dress(task, button)
        if task.children:
            folder = self._folders.get(task.path)
            if folder is None:
                with container:
                    folder = self._folders[task.path] = self.gui.add_folder(f"{task.name} ▾")
            for child in task.children:
                self._update(child, folder)

    def labels(self) -> list[str]:
        """The button labels, in tree order, without the current task's mark (for tests
        and logs)."""
        with self._lock:
            return [self._buttons[path].label.removeprefix(CURRENT) for path in self._tasks]

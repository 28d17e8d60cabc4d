"""Feeding a viewer live: a task listener that sends tree updates and world states."""

from __future__ import annotations

import threading
from typing import Any

from robocram.designators import MotionDesignator
from robocram.execution import Task, TaskListener, TaskSnapshot
from robocram.traces import StoredWorldState
from robocram.viewer.timeline import Moment
from robocram.viewer.viewer import Viewer
from robocram.world import World


class LiveFeed(TaskListener):
    """Sends ``viewer`` each top level's tree and ``world``'s state after every motion."""

    def __init__(self, viewer: Viewer, world: World) -> None:
        self.viewer = viewer
        self.world = world
        self._root: Task | None = None
        self._motions: set[int] = set()
        self._lock = threading.Lock()

    def task_started(self, task: Task) -> None:
        """A new top level resets the tree; every start refreshes it."""
        with self._lock:
            if self._root is None or task.root is not self._root:
                self._root = task.root
                state = StoredWorldState.capture(self.world, task.start_time or 0.0)
                self.viewer.add_moment(Moment(state, None))
        self._refresh()

    def performing(self, task: Task, designator: Any) -> None:
        """Remember which tasks are motions."""
        if isinstance(designator, MotionDesignator):
            with self._lock:
                self._motions.add(id(task))

    def task_finished(self, task: Task) -> None:
        """After a motion, send the world's state; always refresh the tree."""
        with self._lock:
            motion = id(task) in self._motions
            self._motions.discard(id(task))
        if motion:
            state = StoredWorldState.capture(self.world, task.end_time or 0.0)
            self.viewer.add_moment(Moment(state, task.path))
        self._refresh()

    def _refresh(self) -> None:
        root = self._root
        if root is not None:
            self.viewer.set_tree(TaskSnapshot.of(root))

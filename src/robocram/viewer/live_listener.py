"""Feeding a viewer live: a task listener that sends tree updates, world states, costmaps.

The plan's thread only captures the world after each motion (it changes next), keeps the
costmaps locations are resolved through, and marks the tree changed; a feeder thread does
the slow part, drawing and sending to browsers, at most ``MAX_PUSH_RATE`` times a second:
it skips to the newest state, so the viewer barely slows a plan (the feeder's Python work
would otherwise take the plan's turns at the interpreter). Use it as
``with LiveFeed(viewer, world) as feed, listening(feed): ...``.

Projection runs far faster than the robot would move. To be watched, a feed given a
``speed`` paces the plan instead: after each motion the plan waits until the page has
played the motion's trajectories (at ``speed`` times their own pace), every open page
has drawn the state after it, and ``dwell`` seconds (:data:`DWELL` unless told) have
passed, so every state reaches the page and stays long enough to be seen. ``dwell``,
``push_rate`` and ``play_period`` (motion time between two played frames) are the pacing:
a caller that only checks which states arrive (a test) may make them short, or few;
people watching want the defaults.
"""

from __future__ import annotations

import threading
import time
from contextlib import ExitStack
from types import TracebackType
from typing import Any

from robocram.costmaps import Costmap, observing_costmaps
from robocram.designators import MotionDesignator
from robocram.execution import Task, TaskListener, TaskSnapshot, current_task
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.traces import StoredCostmap, StoredWorldState
from robocram.viewer.errors import ViewerArgumentError
from robocram.viewer.timeline import REPLAY_PERIOD, Moment
from robocram.viewer.viewer import Viewer
from robocram.world import World

FLUSH_TIMEOUT = 120.0  # [s] for the feeder to send what is queued when the block ends
MAX_PUSH_RATE = 5.0  # [Hz] pushes to the browsers while a plan runs; every state is kept
DWELL = 0.3  # [s] a paced feed shows each drawn state this long before the plan goes on

Step = tuple[Moment, tuple[JointTrajectory, ...]]  # a state, the trajectories that led to it


class LiveFeed(TaskListener):
    """Sends ``viewer`` each top level's tree and ``world``'s state after every motion."""

    def __init__(
        self,
        viewer: Viewer,
        world: World,
        speed: float | None = None,
        *,
        dwell: float = DWELL,
        push_rate: float = MAX_PUSH_RATE,
        play_period: float = REPLAY_PERIOD,
    ) -> None:
        if speed is not None and not speed > 0.0:
            raise ViewerArgumentError(f"the viewing speed must be positive, got {speed}")
        if not dwell >= 0.0:
            raise ViewerArgumentError(
                f"the dwell must be 0 or more seconds, got {dwell}; e.g. {DWELL} (the default)"
            )
        if not push_rate > 0.0:
            raise ViewerArgumentError(
                f"the push rate must be positive, got {push_rate} Hz; e.g. {MAX_PUSH_RATE}"
            )
        if not play_period > 0.0:
            raise ViewerArgumentError(
                f"the play period must be positive, got {play_period} s; e.g. {REPLAY_PERIOD}"
            )
        self.viewer = viewer
        self.world = world
        self.speed = speed  # None: the plan runs at full speed, the page skips states
        self.dwell = dwell  # [s] a paced feed shows each drawn state this long
        self.push_rate = push_rate  # [Hz] at most this many pushes to the browsers a second
        self.play_period = play_period  # [s] of motion time between two played frames
        self._root: Task | None = None
        self._motions: set[int] = set()
        self._queued: list[Step] = []
        self._executed: list[JointTrajectory] = []  # since the last motion ended (paced)
        self._costmaps: list[StoredCostmap] = []
        self._observing: ExitStack | None = None
        self._tree_changed = False
        self._stopping = False
        self._busy = False
        self._wake = threading.Condition()
        self._thread: threading.Thread | None = None

    def __enter__(self) -> LiveFeed:
        self._stopping = False
        self._observing = ExitStack()
        self._observing.enter_context(observing_costmaps(self.costmap_built))
        if self.speed is not None:
            self._observing.enter_context(trajectory_listener(self.trajectory_executed))
        self._thread = threading.Thread(target=self._feed, name="robocram:live-feed", daemon=True)
        self._thread.start()
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        if self._observing is not None:
            self._observing.close()
        self.flush()
        with self._wake:
            self._stopping = True
            self._wake.notify_all()
        if self._thread is not None:
            self._thread.join(FLUSH_TIMEOUT)

    def flush(self) -> None:
        """Wait until everything queued has been sent to the viewer."""
        with self._wake:
            self._wake.wait_for(
                lambda: not (self._queued or self._costmaps or self._tree_changed or self._busy),
                FLUSH_TIMEOUT,
            )

    def task_started(self, task: Task) -> None:
        """A new top level: capture the world at its start; every start changes the tree."""
        with self._wake:
            if self._root is None or task.root is not self._root:
                self._root = task.root
                state = StoredWorldState.capture(self.world, task.start_time or 0.0)
                self._queued.append((Moment(state, None), ()))
            self._tree_changed = True
            self._wake.notify_all()

    def performing(self, task: Task, designator: Any) -> None:
        """Remember which tasks are motions."""
        if isinstance(designator, MotionDesignator):
            with self._wake:
                self._motions.add(id(task))

    def task_finished(self, task: Task) -> None:
        """After a motion, capture the world's state; always mark the tree changed."""
        with self._wake:
            motion = id(task) in self._motions
            self._motions.discard(id(task))
        state = StoredWorldState.capture(self.world, task.end_time or 0.0) if motion else None
        with self._wake:
            if state is not None:
                executed, self._executed = tuple(self._executed), []
                self._queued.append((Moment(state, task.path), executed))
            self._tree_changed = True
            self._wake.notify_all()
            if state is not None and self.speed is not None:  # paced: the page catches up
                self._wake.wait_for(lambda: not (self._queued or self._busy), FLUSH_TIMEOUT)

    def trajectory_executed(self, trajectory: JointTrajectory) -> None:
        """Keep a trajectory the robot executed, to play it before its motion's end state."""
        with self._wake:
            self._executed.append(trajectory)

    def costmap_built(self, designator: Any, costmap: Costmap) -> None:
        """Keep a costmap a location was resolved through, for the feeder to draw."""
        task = current_task()
        path = None if task is None else task.path
        stored = StoredCostmap.of(costmap, designator, time.time(), path)
        with self._wake:
            self._costmaps.append(stored)
            self._wake.notify_all()

    def _feed(self) -> None:
        pause = 1.0 / self.push_rate
        while True:
            with self._wake:
                self._wake.wait_for(self._has_work)
                if self._stopping and not self._has_work(stopping=False):
                    return
                moments, self._queued = self._queued, []
                costmaps, self._costmaps = self._costmaps, []
                tree_changed, self._tree_changed = self._tree_changed, False
                root, self._busy = self._root, True
            try:
                for costmap in costmaps:
                    self.viewer.add_costmap(costmap)
                if moments:
                    self._show(moments)
                if tree_changed and root is not None:
                    self.viewer.set_tree(TaskSnapshot.of(root))
            finally:
                with self._wake:
                    self._busy = False
                    self._wake.notify_all()
                    self._wake.wait_for(lambda: self._stopping, pause)  # the rate bound

    def _show(self, steps: list[Step]) -> None:
        """Unpaced, the newest state at once; paced, each motion played, each state kept."""
        if self.speed is None:
            self.viewer.add_moments([moment for moment, _ in steps])
            return
        for moment, trajectories in steps:
            for trajectory in trajectories:
                self.viewer.play(trajectory, self.speed, self.play_period)
            self.viewer.add_moments([moment])
            self.viewer.wait_until_drawn()
            time.sleep(self.dwell)

    def _has_work(self, stopping: bool = True) -> bool:
        queued = self._queued or self._costmaps or self._tree_changed
        return bool(queued or (stopping and self._stopping))

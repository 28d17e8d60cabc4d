"""The moments a viewer can show, in time order: stored world states, each after a task, and
in a replay the samples of the trajectories executed between them."""

from __future__ import annotations

import bisect
import threading
from dataclasses import dataclass

from robocram.traces import (
    StoredWorldState,
    TraceDatabase,
    replay_frames,
    world_state_at,
    world_state_times,
)
from robocram.world import World

REPLAY_PERIOD = 0.1  # [s] of motion time between two moments along a trajectory


@dataclass(frozen=True)
class Moment:
    """The world after the motion at ``task_path`` (``None``: the run's start), or during it.

    A moment along a trajectory has ``trajectory`` (its index in the run) and
    ``sample_time`` [s from the trajectory's start] set; ``replay_time`` [s since the epoch]
    places any moment of a replay on the run's replay clock.
    """

    state: StoredWorldState
    task_path: str | None
    replay_time: float | None = None
    trajectory: int | None = None
    sample_time: float = 0.0

    @property
    def time(self) -> float:
        """[s] since the epoch."""
        return self.state.time


class Timeline:
    """Moments in time order; appended live from a plan's thread, read by the viewer."""

    def __init__(self, moments: list[Moment] | None = None) -> None:
        self._moments = sorted(moments or [], key=lambda m: m.time)
        self._lock = threading.Lock()

    @classmethod
    def of_run(cls, db: TraceDatabase, run: int) -> Timeline:
        """Every stored world state of ``run``."""
        return cls(
            [
                Moment(world_state_at(db, run, time), path)
                for _, time, path in world_state_times(db, run)
            ]
        )

    @classmethod
    def of_replay(
        cls, db: TraceDatabase, run: int, world: World, period: float = REPLAY_PERIOD
    ) -> Timeline:
        """Every stored state of ``run`` and its trajectories sampled every ``period`` [s].

        ``world`` holds the run's scene; it is left in the run's last moment.
        """
        moments = []
        for frame in replay_frames(db, run, world, period):
            index = None if frame.trajectory is None else frame.trajectory.index
            state = frame.state or StoredWorldState.capture(world, frame.wall_time)
            moments.append(Moment(state, frame.task_path, frame.time, index, frame.sample_time))
        return cls(moments)

    def add(self, moment: Moment) -> int:
        """Insert ``moment`` in time order; return its index."""
        with self._lock:
            index = bisect.bisect_right([m.time for m in self._moments], moment.time)
            self._moments.insert(index, moment)
            return index

    def __len__(self) -> int:
        with self._lock:
            return len(self._moments)

    def __getitem__(self, index: int) -> Moment:
        with self._lock:
            return self._moments[index]

    def index_at_replay(self, replay_time: float) -> int:
        """The last moment at or before ``replay_time`` [s since the epoch, replay clock]."""
        with self._lock:
            times = [m.replay_time if m.replay_time is not None else m.time for m in self._moments]
        return max(bisect.bisect_right(times, replay_time) - 1, 0)

    def index_at(self, time: float) -> int:
        """The last moment at or before ``time`` [s since the epoch] (0 if none is)."""
        with self._lock:
            times = [m.time for m in self._moments]
        return max(bisect.bisect_right(times, time) - 1, 0)

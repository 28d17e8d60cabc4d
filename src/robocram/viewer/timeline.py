"""The moments a viewer can show: stored world states in time order, each after a task."""

from __future__ import annotations

import bisect
import threading
from dataclasses import dataclass

from robocram.traces import StoredWorldState, TraceDatabase, world_state_at, world_state_times


@dataclass(frozen=True)
class Moment:
    """The world after the motion at ``task_path`` (``None``: the run's start)."""

    state: StoredWorldState
    task_path: str | None

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

    def index_at(self, time: float) -> int:
        """The last moment at or before ``time`` [s since the epoch] (0 if none is)."""
        with self._lock:
            times = [m.time for m in self._moments]
        return max(bisect.bisect_right(times, time) - 1, 0)

"""The replay clock: one time line on which a run's stored states and trajectories play in order.

In projection a motion takes no wall time (the arm is set along its trajectory at once), so
trajectories stamped by the wall clock would all last zero seconds. On a real robot the
wall clock already holds them. The replay clock is the wall clock stretched just enough for
each trajectory to take its own duration: a trajectory starts when the one before it ended
or ``duration`` before it was reported, whichever is later, and every later event moves by
the stretch so far. A run without trajectories keeps its wall times exactly.
Trajectories of two robots moving at once play one after the other.
"""

from __future__ import annotations

import bisect
from collections.abc import Sequence


def replay_starts(run_start: float, reported: Sequence[tuple[float, float]]) -> list[float]:
    """Each trajectory's start [s since the epoch] on the replay clock.

    Args:
        run_start: When the run started [s since the epoch, wall clock].
        reported: ``(time reported [s since the epoch], duration [s])`` per trajectory, in
            execution order.
    """
    starts: list[float] = []
    end, stretch = run_start, 0.0
    for reported_at, duration in reported:
        start = max(end, reported_at + stretch - duration)
        end = start + duration
        stretch = end - reported_at
        starts.append(start)
    return starts


class ReplayClock:
    """Maps wall times of a run's events (world states, task ends) onto the replay clock."""

    def __init__(self, run_start: float, reported: Sequence[tuple[float, float]]) -> None:
        starts = replay_starts(run_start, reported)
        self.run_start = run_start  # [s since the epoch], the same on both clocks
        self._reported = [t for t, _ in reported]  # [s since the epoch], wall clock
        self._stretch = [s + d - t for s, (t, d) in zip(starts, reported, strict=True)]

    def at(self, wall_time: float) -> float:
        """The replay time [s since the epoch] of an event at ``wall_time``.

        An event at the moment a trajectory was reported (its motion's end state) comes
        after that trajectory's end.
        """
        index = bisect.bisect_right(self._reported, wall_time) - 1
        return wall_time + (self._stretch[index] if index >= 0 else 0.0)

    def since_start(self, wall_time: float) -> float:
        """``at(wall_time)`` as seconds from the run's start."""
        return self.at(wall_time) - self.run_start

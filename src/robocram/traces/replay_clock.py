"""The replay clock: one time line on which a run's stored states and trajectories play in order.

In projection a motion takes no wall time (the arm is set along its trajectory at once), so
trajectories stamped by the wall clock would all last zero seconds. On a real robot the
wall clock already holds them. The replay clock is the wall clock stretched just enough for
each trajectory to take its own duration: a trajectory starts ``duration`` before it was
reported, or at the event before it (a world state, the end of the trajectory before)
if that is later, and every later event moves by the stretch so far. A run without
trajectories keeps its wall times exactly.
Trajectories of two robots moving at once play one after the other.
"""

from __future__ import annotations

import bisect
from collections.abc import Sequence


def replay_starts(
    run_start: float, reported: Sequence[tuple[float, float]], events: Sequence[float] = ()
) -> list[float]:
    """Each trajectory's start [s since the epoch] on the replay clock.

    Args:
        run_start: When the run started [s since the epoch, wall clock].
        reported: ``(time reported [s since the epoch], duration [s])`` per trajectory, in
            execution order.
        events: Wall times [s since the epoch] of the run's other events (world states),
            which a trajectory reported after them must not start before.
    """
    starts: list[float] = []
    last, stretch = run_start, 0.0  # replay time of the last event; replay - wall time
    marks = sorted(events)
    next_mark = 0
    for reported_at, duration in reported:
        while next_mark < len(marks) and marks[next_mark] <= reported_at:
            last = max(last, marks[next_mark] + stretch)
            next_mark += 1
        start = max(last, reported_at + stretch - duration)
        last = start + duration
        stretch = last - reported_at
        starts.append(start)
    return starts


class ReplayClock:
    """Maps wall times of a run's events (world states, task ends) onto the replay clock."""

    def __init__(
        self,
        run_start: float,
        reported: Sequence[tuple[float, float]],
        events: Sequence[float] = (),
    ) -> None:
        starts = replay_starts(run_start, reported, events)
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

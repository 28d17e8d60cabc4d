"""Shorter planned paths: shortcuts, then vertex reduction and corner cutting until no
inner waypoint can be dropped.

RRTConnect's path zigzags through the tree. Three counted steps straighten it,
each change accepted only when its new segment is free, checked at the planner's full
resolution (:func:`~robocram.motion.segment_check.segment_free`):

1. **Shortcuts, farthest first.** From the start, each waypoint is joined to the
   farthest waypoint it sees, and so on from there. A blocked try is cheap (the check
   looks at the middle first); a segment kept is seldom replaced later, so few checks go
   into segments thrown away.
2. **Vertex reduction.** Every inner waypoint whose neighbours see each other is
   dropped; the passes repeat until none can be.
3. **Corner cutting** (smoothing, within a counted number of checks). A corner is
   replaced by two points on its segments (half way, else a quarter of the way) where the
   segment between them is free; vertex reduction follows. The path only gets shorter
   (triangle inequality).

The result has no droppable inner waypoint: the last step is always a full vertex
reduction pass that dropped nothing. Each segment remembers whether it was checked at full
resolution (on the checker, a piece of a checked segment is checked: its samples are the
resolution apart along the piece too), so the caller checks again only what the planner
checked coarsely.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from robocram.motion.configuration_checker import ConfigurationChecker
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.segment_check import CheckCounter, segment_free
from robocram.motion.travel_bound import TravelBound

CORNER_CUTS = (0.5, 0.25)  # fractions of a corner's segments tried, in turn
SegmentJudge = Callable[[FloatArray, FloatArray], bool]  # whether a segment is free there too
SMOOTHING_CHECKS = 600  # checks corner cutting may spend (vertex reduction always ends)


@dataclass
class Simplified:
    """A path's waypoints and, per segment, whether it was checked at full resolution."""

    waypoints: list[FloatArray]
    checked: list[bool]

    def unchecked(self) -> list[tuple[FloatArray, FloatArray]]:
        """The segments still to check at full resolution."""
        return [
            (a, b)
            for a, b, done in zip(self.waypoints, self.waypoints[1:], self.checked, strict=False)
            if not done
        ]


def path_length(waypoints: list[FloatArray] | tuple[tuple[float, ...], ...]) -> float:
    """The joint-space length of a polyline [rad | m, Euclidean]."""
    points = np.asarray(waypoints, dtype=float)
    return float(np.linalg.norm(np.diff(points, axis=0), axis=1).sum())


def simplify(
    checker: ConfigurationChecker,
    path: list[FloatArray],
    bound: TravelBound,
    counter: CheckCounter,
    *,
    checked: list[bool] | None = None,
    smoothing: int = SMOOTHING_CHECKS,
    judge: SegmentJudge | None = None,
) -> Simplified:
    """``path`` shortened until no inner waypoint can be dropped.

    ``checked`` says which of its segments are already checked at full resolution
    (default: none); ``smoothing``: the checks corner cutting may spend; ``judge``: a
    second check every new segment must pass too (the world, where the checker is a
    snapshot of it: a path pulled tight round an obstacle must not touch it there).
    """

    def dense(a: FloatArray, b: FloatArray) -> bool:
        return segment_free(checker, a, b, bound, counter)

    return simplify_with(
        SegmentTest(dense, lambda: counter.checks, judge), path, checked=checked,
        smoothing=smoothing,
    )  # fmt: skip


def simplify_with(
    test: SegmentTest,
    path: list[FloatArray],
    *,
    checked: list[bool] | None = None,
    smoothing: int = SMOOTHING_CHECKS,
) -> Simplified:
    """:func:`simplify` with any dense segment check (a base's poses, say)."""
    flags = list(checked) if checked is not None else [False] * (len(path) - 1)
    out = Simplified([np.asarray(w, dtype=float) for w in path], flags)
    _farthest_first(out, test)
    reduce_vertices(out, test)
    limit = test.checks() + smoothing
    while test.checks() < limit and _cut_corners(out, test, limit):
        reduce_vertices(out, test)
    return out


@dataclass
class SegmentTest:
    """A dense segment check at full resolution and how many checks it has spent so far;
    a blocked segment is not checked twice."""

    dense: SegmentJudge
    checks: Callable[[], int]
    judge: SegmentJudge | None = None
    blocked: set[bytes] = field(default_factory=set)

    def __call__(self, a: FloatArray, b: FloatArray) -> bool:
        key = a.tobytes() + b.tobytes()
        if key in self.blocked:
            return False
        if self.dense(a, b) and self.judged(a, b):
            return True
        self.blocked.add(key)
        return False

    def judged(self, a: FloatArray, b: FloatArray) -> bool:
        """Whether a piece of a checked segment is free: the checker's samples along the
        whole segment are at most the resolution apart along the piece too, but the judge
        walks the piece as it is (a walk by clearances samples where it steps)."""
        return self.judge is None or self.judge(a, b)


def _farthest_first(path: Simplified, free: SegmentTest) -> None:
    """From the start, join each waypoint to the farthest one it sees, and go on from
    there: blocked tries are cheap (the check looks at the middle first), and the segments
    kept are seldom replaced later, so few checks go into segments thrown away."""
    points, flags = path.waypoints, path.checked
    kept, kept_flags = [points[0]], []
    i = 0
    while i < len(points) - 1:
        for j in range(len(points) - 1, i, -1):
            if j == i + 1:
                kept_flags.append(flags[i])
                break
            if free(points[i], points[j]):
                kept_flags.append(True)
                break
        kept.append(points[j])
        i = j
    path.waypoints, path.checked = kept, kept_flags


def reduce_vertices(path: Simplified, free: SegmentTest) -> None:
    """Drop inner waypoints whose neighbours see each other, until none can be."""
    dropped = True
    while dropped:
        dropped = False
        k = 1
        while k < len(path.waypoints) - 1:
            points = path.waypoints
            if free(points[k - 1], points[k + 1]):
                del points[k]
                path.checked[k - 1 : k + 1] = [True]
                dropped = True
            else:
                k += 1


def _cut_corners(path: Simplified, free: SegmentTest, limit: int) -> bool:
    """Replace each corner by two points on its segments where they see each other, until
    ``limit`` checks are spent; whether any corner was cut. The pieces left of the
    corner's segments need no new check on the checker (its samples along the whole
    segment are the resolution apart along the piece too); the judge walks them."""
    points, flags = [path.waypoints[0]], []
    cut = False
    for k in range(1, len(path.waypoints) - 1):
        before, corner, after = path.waypoints[k - 1], path.waypoints[k], path.waypoints[k + 1]
        for fraction in CORNER_CUTS if free.checks() < limit else ():
            p = corner + (before - corner) * fraction
            r = corner + (after - corner) * fraction
            if free(p, r) and free.judged(before, p) and free.judged(r, after):
                points += [p, r]
                flags += [path.checked[k - 1], True]  # a piece is checked if its segment is
                cut = True
                break
        else:
            points.append(corner)
            flags.append(path.checked[k - 1])
        path.waypoints[k] = points[-1]  # the next corner starts from what replaced this one
    points.append(path.waypoints[-1])
    flags.append(path.checked[-1])
    path.waypoints, path.checked = points, flags
    return cut

"""A collision-free joint-space path: the straight segment when it is free, else RRTConnect.

Like MoveIt, the straight segment from start to goal is tried first, checked densely
(:mod:`travel_bound`). When it is blocked, OMPL's RRTConnect plans in the same joints
(the arm's, and the torso when IK moved it), and the path is simplified until no inner
waypoint can be dropped (:mod:`path_simplification`). Everything is counted and seeded,
so a query gives the same path on any machine. A goal the planner cannot connect within
its budget raises ``ManipulationPathBlocked`` naming what the straight segment runs into, and where.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

import numpy as np

from robocram.execution.failures import ManipulationPathBlocked
from robocram.motion.configuration_checker import ConfigurationChecker
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.path_simplification import SegmentJudge, simplify
from robocram.motion.rrt_connect import rrt_connect
from robocram.motion.segment_check import CheckCounter, first_collision, segment_free
from robocram.motion.travel_bound import TravelBound

PLANNING_BUDGET = 5_000  # configurations RRTConnect may check (a plan round the box: ~300)
COARSE = 16  # RRTConnect checks its tree edges this much coarser; the path is then re-checked
PLANNING_ATTEMPTS = 3  # plans (seed, seed + 1, ...) whose re-check may fail before giving up


@dataclass(frozen=True)
class JointPath:
    """Waypoints of a path through ``joints``; ``planner`` says how it was found."""

    joints: tuple[str, ...]
    waypoints: tuple[tuple[float, ...], ...]
    planner: str  # "straight", "detour", "rrt_connect" or "cartesian"
    checks: int  # configurations checked to find it


def plan_joint_path(
    checker: ConfigurationChecker,
    start: Sequence[float],
    goal: Sequence[float],
    bound: TravelBound,
    limits: tuple[Sequence[float], Sequence[float]],
    *,
    plan: bool = True,
    seed: int = 0,
    budget: int = PLANNING_BUDGET,
    what: str = "the arm",
    explain: bool = True,
    judge: SegmentJudge | None = None,
    start_free: bool = False,
    start_travels: Mapping[str, float] | None = None,
) -> JointPath:
    """A free path from ``start`` to ``goal`` (both free); ``plan=False``: straight only.

    ``limits`` are the joints' (lower, upper) bounds of the planning space. ``explain``
    False skips finding what the straight segment runs into first (a walk at full
    resolution), for a caller that will plan elsewhere and explain from there. ``judge``:
    a second check every segment of a planned path must pass (the world, when ``checker``
    is a snapshot of it), while it is simplified and after. ``start_free``: the caller
    made ``checker`` allowing the contacts it found at ``start`` (the world stands there
    still), so the start is not asked again. ``start_travels``: per link,
    :func:`~robocram.motion.segment_check.start_travel` of the straight segment, worked
    out by the caller as the robot stands at ``start`` (the walk takes it as it is).

    Raises:
        ManipulationPathBlocked: neither the straight segment nor the planner found a way;
            it names the pairs colliding first on the straight segment and where.
    """
    counter = CheckCounter()
    a, b = np.asarray(start, dtype=float), np.asarray(goal, dtype=float)
    joints = checker.joints
    ends = (("start", a, 0.0), ("goal", b, 1.0))
    for end, q, fraction in ends[1:] if start_free else ends:
        pairs = checker.colliding(q)
        if pairs:
            raise ManipulationPathBlocked(
                f"{what}'s {end} configuration is in collision: {_pairs(pairs)}",
                colliding_pairs=tuple(pairs),
                path_fraction=fraction,
            )
    if segment_free(checker, a, b, bound, counter, start_travels):
        return JointPath(joints, (tuple(a), tuple(b)), "straight", counter.checks)
    if plan:
        lower, upper = planning_box(a, b, limits)
        coarse = replace(
            bound,
            max_link_travel=COARSE * bound.max_link_travel,
            max_joint_step=COARSE * bound.max_joint_step,
        )
        for attempt in range(PLANNING_ATTEMPTS):
            found = rrt_connect(
                checker, a, b, lower, upper, coarse, counter, budget, seed + attempt
            )
            if found is None:
                break
            simple = simplify(checker, found, bound, counter, judge=judge)
            if all(
                segment_free(checker, qa, qb, bound, counter) and (judge is None or judge(qa, qb))
                for qa, qb in simple.unchecked()
            ):
                return JointPath(
                    joints, tuple(tuple(map(float, w)) for w in simple.waypoints),
                    "rrt_connect", counter.checks,
                )  # fmt: skip
    if not explain:
        raise ManipulationPathBlocked(
            f"{what}'s straight path is blocked", colliding_pairs=(), path_fraction=0.0
        )
    hit = first_collision(checker, a, b, bound, counter)
    fraction, pairs = hit if hit is not None else (0.0, [])
    planned = f"; RRTConnect found no way round in {budget} checks" if plan else ""
    raise ManipulationPathBlocked(
        f"{what}'s straight path is blocked {fraction:.0%} of the way: {_pairs(pairs)}{planned}",
        colliding_pairs=tuple(pairs),
        path_fraction=fraction,
    )


def planning_box(
    a: FloatArray, b: FloatArray, limits: tuple[Sequence[float], Sequence[float]]
) -> tuple[list[float], list[float]]:
    """The planning space: the joint limits, continuous joints within a turn of the ends."""
    lower, upper = [], []
    for i, (lo, hi) in enumerate(zip(*limits, strict=True)):
        low_end, high_end = min(a[i], b[i]), max(a[i], b[i])
        lower.append(float(lo) if np.isfinite(lo) else low_end - np.pi)
        upper.append(float(hi) if np.isfinite(hi) else high_end + np.pi)
    return lower, upper


def _pairs(pairs: Sequence[tuple[str, str]]) -> str:
    if not pairs:
        return "no collision found on it (a state on the way is invalid)"
    return ", ".join(f"{link} hits {other}" for link, other in pairs[:4])

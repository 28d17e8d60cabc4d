"""Around obstacles: OMPL plans the base in SE(2) (RRTConnect), or as a Reeds-Shepp car.

A holonomic base's path is shortened by :mod:`path_simplification` (until no waypoint can
be dropped), a car's by OMPL's simplifier. Every motion asked about, while planning and
while shortening the path, is checked densely by the
:class:`~robocram.motion.base_collision.BaseCollisionChecker` (a motion validator of ours,
not OMPL's sparse one), so the path that comes out is checked densely.
Planning and shortening stop on a counted budget of fast checks, never on the clock, and
OMPL's random numbers are seeded right before the query; OMPL's generator is process-wide,
so queries take turns (a lock).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.base_collision import BaseCollisionChecker
from robocram.motion.ompl_query import POLLS_PER_CHECK, OmplQuery
from robocram.motion.path_simplification import SegmentTest, simplify_with
from robocram.motion.planar_motion import reeds_shepp_poses, straight_poses, wrapped
from robocram.motion.reeds_shepp_sampler import sampler_for
from robocram.motion.robot_footprint import FloatArray
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    from ompl import base as ob
    from ompl import geometric as og
else:
    ob = LazyLibrary("ompl.base")
    og = LazyLibrary("ompl.geometric")

Area = tuple[tuple[float, float], tuple[float, float]]  # [m] lower and upper x, y in map
SIMPLIFY_SHARE = 0.25  # of the budget, added for shortening a car's path (OMPL's simplifier)
SMOOTHING_CHECKS = 1_000  # fast checks corner cutting may spend on a holonomic base's path
PREVIEW = 8  # the simplifier checks every 8th pose first: a blocked shortcut is refused sooner
# [m, in SE(2)'s distance] longest tree edge. OMPL's default, a fifth of the planning
# area's extent, is metres in a flat whose walls run 19 m: every extension into a cluttered
# corner is a long edge, blocked, and its dense check spends the budget growing nothing.
TREE_STEP = 0.5


@functools.cache
def _dense_motions() -> type:
    """The motion validator class, made at first use: it subclasses OMPL's, loaded then."""

    class _DenseMotions(ob.MotionValidator):
        """OMPL's question "is this motion free?", answered by our dense check."""

        def __init__(self, si: ob.SpaceInformation, free: Callable[[object, object], bool]):
            super().__init__(si)
            self._free = free

        def checkMotion(self, s1: object, s2: object) -> bool:  # noqa: N802 (OMPL's name)
            return self._free(s1, s2)

    return _DenseMotions


def motion_poses(
    checker: BaseCollisionChecker,
    start: FloatArray,
    end: FloatArray,
    turning_radius: float | None,
) -> FloatArray:
    """Dense poses of the base's motion ``start`` -> ``end`` (a car's if ``turning_radius``)."""
    reach = checker.footprint.reach
    if turning_radius is None:
        return straight_poses(start, end, reach)
    return reeds_shepp_poses(sampler_for(turning_radius), start, end, reach)


def planned_waypoints(
    checker: BaseCollisionChecker,
    start: FloatArray,
    goal: FloatArray,
    *,
    turning_radius: float | None,
    seed: int,
    budget: int,
    coarse: int = 1,
    area: Area | None = None,
) -> list[FloatArray] | None:
    """Waypoints of a free path (None within ``budget`` fast checks); straight between them.

    For a car (``turning_radius`` given) the waypoints are the dense poses along its curves.
    ``coarse``: tree edges are checked at every ``coarse``-th dense pose (and the last), so
    the caller checks the answer densely again. ``area``: where to sample (default: the
    checker's bounds).
    """
    if turning_radius is None:
        space: ob.StateSpace = ob.SE2StateSpace()
    else:
        space = ob.ReedsSheppStateSpace(turning_radius)
    lower, upper = area if area is not None else checker.bounds
    bounds = ob.RealVectorBounds(2)
    for axis in (0, 1):
        bounds.setLow(axis, lower[axis])
        bounds.setHigh(axis, upper[axis])
    space.setBounds(bounds)
    setup = og.SimpleSetup(space)
    setup.setStateValidityChecker(lambda s: checker.pose_free(_pose(s)))
    info = setup.getSpaceInformation()

    def free(s1: object, s2: object) -> bool:
        poses = motion_poses(checker, _pose(s1), _pose(s2), turning_radius)
        if coarse > 1:
            poses = np.concatenate([poses[::coarse], poses[-1:]])
        return checker.first_blocked(poses) is None

    validator = _dense_motions()(info, free)
    info.setMotionValidator(validator)
    planner = og.RRTConnect(info)
    planner.setRange(TREE_STEP)
    setup.setPlanner(planner)
    ends = []
    for pose in (start, goal):
        state = space.allocState()
        state.setX(float(pose[0]))
        state.setY(float(pose[1]))
        state.setYaw(wrapped(float(pose[2])))
        ends.append(state)
    setup.setStartAndGoalStates(ends[0], ends[1])
    limit = checker.fast_checks + budget
    checker.confirm_everywhere = False
    polls = POLLS_PER_CHECK * budget
    try:
        with OmplQuery(seed, lambda: checker.fast_checks > limit, polls) as query:
            setup.solve(query.condition())
            if not setup.haveExactSolutionPath():
                return None
            if turning_radius is not None:
                extra = checker.fast_checks + int(SIMPLIFY_SHARE * budget)
                setup.simplifySolution(query.condition(lambda: checker.fast_checks > extra))
            states = [_pose(s) for s in setup.getSolutionPath().getStates()]
    finally:
        checker.confirm_everywhere = True
    path = _unwrapped(checker, states, turning_radius)
    if turning_radius is not None:
        return path
    checker.confirm_everywhere = False
    try:
        return simplify_with(_straight_test(checker), path, smoothing=SMOOTHING_CHECKS).waypoints
    finally:
        checker.confirm_everywhere = True


def _straight_test(checker: BaseCollisionChecker) -> SegmentTest:
    """The dense check of a holonomic base's straight motion, for the simplifier: a motion
    turning more than half a turn is refused (checked the short way round, it would be
    driven the long way: the path's headings are continuous)."""

    def free(a: FloatArray, b: FloatArray) -> bool:
        if abs(b[2] - a[2]) > np.pi:
            return False
        poses = motion_poses(checker, a, b, None)
        coarse = np.concatenate([poses[::PREVIEW], poses[-1:]])
        return checker.first_blocked(coarse) is None and checker.first_blocked(poses) is None

    return SegmentTest(free, lambda: checker.fast_checks)


def _unwrapped(
    checker: BaseCollisionChecker,
    states: list[FloatArray],
    turning_radius: float | None,
) -> list[FloatArray]:
    """The path's poses with continuous headings (a car's: dense along its curves)."""
    out = [states[0]]
    for state in states[1:]:
        if turning_radius is None:
            yaw = out[-1][2] + wrapped(state[2] - out[-1][2])
            out.append(np.array([state[0], state[1], yaw]))
        else:
            dense = motion_poses(checker, out[-1], state, turning_radius)
            out += list(dense[1:])
    return out


def _pose(state: object) -> FloatArray:
    return np.array([state.getX(), state.getY(), state.getYaw()])  # type: ignore[attr-defined]

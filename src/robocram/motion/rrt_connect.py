"""OMPL's RRTConnect (MoveIt's default planner) in a robot's joint space, made repeatable.

Queries are seeded, locked and budgeted by :mod:`ompl_query`: the same query and seed
give the same path in any process, on an idle or a loaded machine, and a stopped task
ends the search at once. Motions between tree states are checked
with the same dense segment check as every other path (:mod:`segment_check`).
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.configuration_checker import ConfigurationChecker
from robocram.motion.errors import MotionError
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.ompl_query import POLLS_PER_CHECK, OmplQuery
from robocram.motion.segment_check import CheckCounter, segment_free
from robocram.motion.travel_bound import TravelBound
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    from ompl import base as ob
    from ompl import geometric as og
else:
    ob = LazyLibrary("ompl.base")
    og = LazyLibrary("ompl.geometric")

RANGE = 1.5  # [rad] longest tree edge: long edges checked coarsely reach round in few states


@functools.cache
def _dense_motions() -> type:
    """The motion validator class, made at first use: it subclasses OMPL's, loaded then."""

    class _DenseMotions(ob.MotionValidator):
        """OMPL asks whether a tree edge is free; the dense segment check answers."""

        def __init__(
            self,
            si: ob.SpaceInformation,
            checker: ConfigurationChecker,
            bound: TravelBound,
            counter: CheckCounter,
            width: int,
        ) -> None:
            super().__init__(si)
            self._checker = checker
            self._bound = bound
            self._counter = counter
            self._width = width

        def checkMotion(self, s1: ob.State, s2: ob.State, *rest: object) -> bool:  # noqa: N802
            a = np.array([s1[i] for i in range(self._width)])
            b = np.array([s2[i] for i in range(self._width)])
            self._counter.checks += 1
            if not self._checker.is_free(b):  # OMPL takes s1 as valid, not s2
                return False
            return segment_free(self._checker, a, b, self._bound, self._counter)

    return _DenseMotions


def rrt_connect(
    checker: ConfigurationChecker,
    start: FloatArray,
    goal: FloatArray,
    lower: Sequence[float],
    upper: Sequence[float],
    bound: TravelBound,
    counter: CheckCounter,
    budget: int,
    seed: int,
) -> list[FloatArray] | None:
    """Waypoints from ``start`` to ``goal`` within the box ``lower``..``upper``, or None
    when ``budget`` configuration checks found none."""
    width = len(start)
    for i in range(width):
        if not (np.isfinite(lower[i]) and np.isfinite(upper[i]) and lower[i] < upper[i]):
            raise MotionError(
                f"planning bounds of joint {i} are [{lower[i]}, {upper[i]}]: they must be "
                "finite and increasing (joint_path.planning_box gives continuous joints a turn)"
            )
    space = ob.RealVectorStateSpace(width)
    bounds = ob.RealVectorBounds(width)
    for i in range(width):
        bounds.setLow(i, float(lower[i]))
        bounds.setHigh(i, float(upper[i]))
    space.setBounds(bounds)
    setup = og.SimpleSetup(space)
    si = setup.getSpaceInformation()

    def valid(state: ob.State) -> bool:
        counter.checks += 1
        return checker.is_free([state[i] for i in range(width)])

    setup.setStateValidityChecker(valid)
    validator = _dense_motions()(si, checker, bound, counter, width)
    si.setMotionValidator(validator)
    a, b = space.allocState(), space.allocState()
    for i in range(width):
        a[i], b[i] = float(start[i]), float(goal[i])
    setup.setStartAndGoalStates(a, b)
    planner = og.RRTConnect(si)
    planner.setRange(RANGE)
    setup.setPlanner(planner)
    limit = counter.checks + budget
    with OmplQuery(seed, lambda: counter.checks > limit, POLLS_PER_CHECK * budget) as query:
        solved = setup.solve(query.condition())
        if not solved or not setup.haveExactSolutionPath():
            return None
        states = setup.getSolutionPath().getStates()
        path = [np.array([s[i] for i in range(width)]) for s in states]
    del validator
    return path

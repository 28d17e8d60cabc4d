"""Evenly spaced states along OMPL's shortest Reeds-Shepp curve, the curve computed once.

``ReedsSheppStateSpace.interpolate(a, b, t, out)`` solves the whole curve (every word
family) again for each ``t``: a dense motion of a hundred poses solved it a hundred times,
a tenth of a drafted Stretch's breakfast CPU (issue 40). OMPL's C++ keeps the solved curve
while it walks one motion in its Reeds-Shepp motion validator, which the Python bindings
expose (the curve and the interpolation along it are not). So the sampler asks that
validator about the motion, with a validity checker that only records each state it is
shown and calls it valid: every state is OMPL's own interpolation at ``j / n`` along the
same curve, bit for bit what ``interpolate`` gives. The validator visits them in its own
order (ends and halves first); the order depends on ``n`` alone and is read once per ``n``
from a straight motion, whose states lie in order of x.
"""

from __future__ import annotations

import atexit
import functools
import threading
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.robot_footprint import FloatArray
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    from ompl import base as ob
else:
    ob = LazyLibrary("ompl.base")

EXTENT = 1.0e4  # [m] the sampler's bounds either way: far beyond any motion it samples
SEGMENT_FRACTION = 0.99  # of the extent: one "segment" holds every motion, n is the factor


class ReedsSheppSampler:
    """States at ``j / n`` (j = 1..n) along the shortest Reeds-Shepp curve of a car of
    ``turning_radius`` [m] between two poses, from OMPL, the curve solved once per motion.

    One sampler may be shared by threads (a lock); OMPL's states are its own.
    """

    def __init__(self, turning_radius: float) -> None:
        self.turning_radius = turning_radius
        space = ob.ReedsSheppStateSpace(turning_radius)
        bounds = ob.RealVectorBounds(2)
        bounds.setLow(-EXTENT)
        bounds.setHigh(EXTENT)
        space.setBounds(bounds)
        space.setLongestValidSegmentFraction(SEGMENT_FRACTION)
        info = ob.SpaceInformation(space)
        self._seen: list[float] = []  # x, y, yaw of each state shown, flat
        info.setStateValidityChecker(_recorder(self._seen))  # no cycle through OMPL's C++
        info.setup()
        self._space, self._info = space, info  # the validator holds on to neither
        self._validator = ob.ReedsSheppMotionValidator(info)
        self._orders: dict[int, np.ndarray | None] = {}
        self._lock = threading.Lock()
        self._a, self._b, self._out = space.allocState(), space.allocState(), space.allocState()

    def length(self, start: FloatArray, end: FloatArray) -> float:
        """[m] The shortest curve's length from ``start`` to ``end`` (x, y, yaw in
        [-pi, pi))."""
        with self._lock:
            self._set(start, end)
            return float(self._space.distance(self._a, self._b))

    def states(self, start: FloatArray, end: FloatArray, n: int) -> FloatArray:
        """(n, 3) x, y and OMPL's yaw at ``j / n`` (j = 1..n) along the curve from ``start``
        to ``end`` (yaws in [-pi, pi)); the last is ``end`` itself, as OMPL gives it."""
        with self._lock:
            order = self._order(n)  # before the ends are set: it samples a motion of its own
            self._set(start, end)
            if order is None or self._segments(n) != n:
                return self._one_by_one(n)  # the validator would not cut it in n
            self._seen.clear()
            self._validator.checkMotion(self._a, self._b)
            if len(self._seen) != 3 * n:
                return self._one_by_one(n)
            return np.array(self._seen).reshape(n, 3)[order]

    def _set(self, start: FloatArray, end: FloatArray) -> None:
        for state, pose in ((self._a, start), (self._b, end)):
            state.setX(float(pose[0]))
            state.setY(float(pose[1]))
            state.setYaw(float(pose[2]))

    def _segments(self, n: int) -> int:
        """How many pieces the validator cuts the current motion into when told ``n``."""
        self._space.setValidSegmentCountFactor(n)
        return int(self._space.validSegmentCount(self._a, self._b))

    def _one_by_one(self, n: int) -> FloatArray:
        """:meth:`states` by OMPL's ``interpolate``, the curve solved for each state: for
        a motion the validator cuts otherwise (standing still: no pieces)."""
        space, a, b, out = self._space, self._a, self._b, self._out
        rows = []
        for k in range(1, n + 1):
            space.interpolate(a, b, k / n, out)
            rows.append((out.getX(), out.getY(), out.getYaw()))
        return np.array(rows, dtype=float).reshape(n, 3)

    def _order(self, n: int) -> np.ndarray | None:
        """Indices putting the validator's ``n`` states in order along the curve (None if
        it did not show n distinct states in a straight motion), read once per ``n``."""
        if n not in self._orders:
            self._a.setX(0.0)
            self._a.setY(0.0)
            self._a.setYaw(0.0)
            self._b.setX(1.0)
            self._b.setY(0.0)
            self._b.setYaw(0.0)
            found: np.ndarray | None = None
            if self._segments(n) == n:
                self._seen.clear()
                self._validator.checkMotion(self._a, self._b)
                xs = np.array(self._seen[0::3])
                order = np.argsort(xs, kind="stable")
                if len(xs) == n and bool(np.all(np.diff(xs[order]) > 0.0)):
                    found = order
            self._orders[n] = found
        return self._orders[n]


def _recorder(seen: list[float]) -> Callable[[object], bool]:
    """OMPL's validity question, answered "valid" after keeping the state in ``seen``."""

    def record(state: object) -> bool:
        seen.extend((state.getX(), state.getY(), state.getYaw()))  # type: ignore[attr-defined]
        return True

    return record


@functools.lru_cache(maxsize=8)
def sampler_for(turning_radius: float) -> ReedsSheppSampler:
    """The process's sampler for cars of ``turning_radius`` [m]: its orders are read once."""
    return ReedsSheppSampler(turning_radius)


# freed before the interpreter unloads OMPL, which otherwise reports the samplers as leaked
atexit.register(sampler_for.cache_clear)

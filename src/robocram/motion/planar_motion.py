"""Base motions between two poses ``(x, y, yaw)``, as densely spaced poses to check.

A holonomic base goes straight: x and y linearly, the heading the short way round. A car
(Reeds-Shepp) follows OMPL's shortest Reeds-Shepp curve. Either is cut into steps in which
no point of the robot (within ``reach`` of the base origin) moves more than 1 cm and the
heading no more than 0.02 rad. Headings come out unwrapped (continuous along the poses).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.base_collision import planar_steps
from robocram.motion.robot_footprint import FloatArray
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    from ompl import base as ob
else:
    ob = LazyLibrary("ompl.base")


def wrapped(angle: float) -> float:
    """``angle`` [rad] brought into [-pi, pi).

    Rounding can bring an angle just below -pi to +pi, which OMPL's SE(2) bounds refuse (a
    goal it refuses is waited for until the budget's polls run out): that is taken back.
    """
    value = (angle + math.pi) % (2.0 * math.pi) - math.pi
    return value if value < math.pi else value - 2.0 * math.pi


def straight_poses(start: FloatArray, end: FloatArray, reach: float) -> FloatArray:
    """Dense poses from ``start`` to ``end``, straight in x, y and the short way in yaw."""
    delta = np.array([end[0] - start[0], end[1] - start[1], wrapped(end[2] - start[2])])
    steps = planar_steps(math.hypot(delta[0], delta[1]), float(delta[2]), reach)
    fractions = np.linspace(0.0, 1.0, steps + 1)[:, None]
    return np.asarray(start, dtype=float)[None, :] + fractions * delta[None, :]


def reeds_shepp_poses(
    space: ob.ReedsSheppStateSpace, start: FloatArray, end: FloatArray, reach: float,
    turning_radius: float,
) -> FloatArray:  # fmt: skip
    """Dense poses along the shortest Reeds-Shepp curve from ``start`` to ``end``."""
    a, b, out = space.allocState(), space.allocState(), space.allocState()
    for state, pose in ((a, start), (b, end)):
        state.setX(float(pose[0]))
        state.setY(float(pose[1]))
        state.setYaw(wrapped(float(pose[2])))
    length = float(space.distance(a, b))
    steps = planar_steps(length, length / turning_radius, reach)
    poses = [np.asarray(start, dtype=float)]
    for k in range(1, steps + 1):
        space.interpolate(a, b, k / steps, out)
        yaw = poses[-1][2] + wrapped(out.getYaw() - poses[-1][2])
        poses.append(np.array([out.getX(), out.getY(), yaw]))
    return np.array(poses)

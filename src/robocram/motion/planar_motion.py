"""Base motions between two poses ``(x, y, yaw)``, as densely spaced poses to check.

A holonomic base goes straight: x and y linearly, the heading the short way round. A car
(Reeds-Shepp) follows OMPL's shortest Reeds-Shepp curve (:mod:`reeds_shepp_sampler`).
Either is cut into steps in which no point of the robot (within ``reach`` of the base
origin) moves more than 1 cm and the heading no more than 0.02 rad. Headings come out
unwrapped (continuous along the poses).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.base_collision import planar_steps
from robocram.motion.robot_footprint import FloatArray

if TYPE_CHECKING:
    from robocram.motion.reeds_shepp_sampler import ReedsSheppSampler


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
    sampler: ReedsSheppSampler, start: FloatArray, end: FloatArray, reach: float
) -> FloatArray:
    """Dense poses along the shortest Reeds-Shepp curve from ``start`` to ``end``."""
    ends = [np.array([pose[0], pose[1], wrapped(float(pose[2]))], dtype=float)
            for pose in (start, end)]  # fmt: skip
    length = sampler.length(ends[0], ends[1])
    steps = planar_steps(length, length / sampler.turning_radius, reach)
    states = sampler.states(ends[0], ends[1], steps)
    poses = np.empty((steps + 1, 3))
    poses[0] = start
    poses[1:, :2] = states[:, :2]
    yaw, yaws = float(poses[0, 2]), []
    for heading in states[:, 2].tolist():  # unwrapped: each the short way from the last
        yaw += wrapped(heading - yaw)
        yaws.append(yaw)
    poses[1:, 2] = yaws
    return poses

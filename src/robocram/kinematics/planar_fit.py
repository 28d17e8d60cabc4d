"""Where a planar base move lays an arm's sampled tool poses onto a target: IK starts.

A move of the base by (x, y, yaw) turns every tool pose about the vertical and shifts it
horizontally; it cannot change the tool's height or its tilt. For each configuration of
the arm's start table the best such move is found in closed form: the yaw that best turns
the sample's orientation onto the target's (the rotation about z nearest, in the Frobenius
sense, to ``R_target R_sample^T``), then the shift that puts the positions over each other.
What is left (height and tilt, weighted like the table's pose distance) is the misfit.
Starts are ranked by misfit plus a cost on the move, so that small base motions come first.

A differential base reaches the same move by turning towards it (or away, to back up),
driving and turning to the yaw; its start is given in those variables, and its move costs
the drive and both turns. A move sideways thus costs two turns: IK prefers the poses a
drive reaches along its heading, not those that need it to turn about near the furniture.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from robocram.kinematics.arm_chain import FloatArray
from robocram.kinematics.planar_base import MAX_TURN, PlanarBase
from robocram.kinematics.seed_table import ROTATION_WEIGHT, SeedTable
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

MOTION_WEIGHT = 0.1  # cost per metre of base travel, against metres of misfit
TURN_WEIGHT = 0.3  # [m/rad] a turn of the base counts like this much travel per radian
_ENTRIES = ((0, 0), (0, 1), (1, 0), (1, 1), (2, 2))  # of R_target R_sample^T the fit uses


class PlanarFits(NamedTuple):
    """Starts (base x, y, yaw, then the arm's variables), cheapest first, and their costs."""

    starts: FloatArray
    cost: FloatArray  # [m] misfit plus weighted base motion


def planar_fits(
    table: SeedTable, arm_base: pin.SE3, target: pin.SE3, base: PlanarBase, count: int
) -> PlanarFits:
    """The ``count`` cheapest starts from ``table`` for ``target`` (root link frame).

    ``arm_base`` is the pose, in the root link, of the frame the table's tool poses are
    given in. Moves beyond ``base``'s travel are left out.
    """
    rb, tb = arm_base.rotation, arm_base.translation
    position = table.features[:, :3] @ rb.T + tb
    # m = R_target (Rb R_sample)^T = A R_sample^T B with A = R_target, B = Rb^T, so each
    # entry m[i, k] = sum over (l, j) of R_sample[l, j] A[i, j] B[l, k]: one product with
    # the table's flattened rotations gives the five entries the fit needs
    a, b = target.rotation, rb.T
    weights = np.column_stack([np.outer(b[:, k], a[i]).ravel() for i, k in _ENTRIES])
    m = table.features[:, 3:] @ (weights / ROTATION_WEIGHT)
    m00, m01, m10, m11, m22 = m.T
    yaw = np.arctan2(m10 - m01, m00 + m11)
    c, s = np.cos(yaw), np.sin(yaw)
    goal = target.translation
    x = goal[0] - (c * position[:, 0] - s * position[:, 1])
    y = goal[1] - (s * position[:, 0] + c * position[:, 1])
    trace = c * (m00 + m11) + s * (m10 - m01) + m22
    tilt2 = np.maximum(6.0 - 2.0 * trace, 0.0)  # |Rz R_sample - R_target|_F^2
    misfit = np.sqrt((goal[2] - position[:, 2]) ** 2 + ROTATION_WEIGHT**2 * tilt2)
    variables = _differential(x, y, yaw) if base.differential else np.column_stack((x, y, yaw))
    if base.differential:
        turns = np.abs(variables[:, 0]) + np.abs(variables[:, 2])
        motion = np.abs(variables[:, 1]) + TURN_WEIGHT * turns
    else:
        motion = np.hypot(x, y) + TURN_WEIGHT * np.abs(yaw)
    cost = misfit + MOTION_WEIGHT * motion
    inside = (np.abs(x) <= base.travel_x) & (np.abs(y) <= base.travel_y)
    inside &= np.abs(yaw) <= base.travel_yaw
    rows = np.flatnonzero(inside)
    if rows.size > count:
        rows = rows[np.argpartition(cost[rows], count)[:count]]
    rows = rows[np.argsort(cost[rows], kind="stable")]
    starts = np.hstack((variables[rows], table.configurations[rows]))
    return PlanarFits(starts, cost[rows])


def _differential(x: FloatArray, y: FloatArray, yaw: FloatArray) -> FloatArray:
    """Moves ``(x, y, yaw)`` as a differential base's (turn, drive, turn), the first turn at
    most a quarter each way (beyond, the base backs up)."""
    turn = np.arctan2(y, x)
    drive = np.hypot(x, y)
    back = np.abs(turn) > MAX_TURN
    turn = np.where(back, turn - np.copysign(np.pi, turn), turn)
    drive = np.where(back, -drive, drive)
    turn = np.where(drive == 0.0, 0.0, turn)
    last = np.remainder(yaw - turn + np.pi, 2 * np.pi) - np.pi
    return np.column_stack((turn, drive, last))

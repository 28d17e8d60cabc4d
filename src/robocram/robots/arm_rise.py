"""The rise at an arm's shoulder: the part of its first segment along its first joint's axis.

A turning first joint carries what lies along its axis round without taking it any
farther out: an arm whose second joint sits 0.10 m above a vertical first one reaches out
from the top of that rise, and its stretched length past that point is shorter by the
rise. :func:`~robocram.robots.arm_envelope.arm_reach` counts the rise (the stands' checks
and Boxy's scenes rely on it as it is); a scene that asks whether a hand spot is in reach
asks it from the top of the rise instead (:mod:`robocram.scenes.placement`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from robocram.robots.arm_envelope import arm_reach, lift_joints
from robocram.robots.description import ArmDescription
from robocram.robots.model_pose import link_pose
from robocram.robots.robot_model import RobotModel
from robocram.tf import Pose


@dataclass(frozen=True)
class ArmRise:
    """Where an arm reaches out from, past the rise along its first joint's axis."""

    rise: tuple[float, float, float]  # [m] base frame: shoulder to the top of the rise
    reach: float  # [m] from the top of the rise to the wrist, stretched: the arm's reach
    # less its first segment, plus that segment's part across the axis (it turns out)


def arm_rise(
    model: RobotModel, arm: ArmDescription, fixed: Mapping[str, float] | None = None
) -> ArmRise:
    """The rise at ``arm``'s shoulder (its first joint after a lift) and its reach past it,
    ``fixed`` joints held (a lift at its middle, as :func:`arm_reach` holds it); no rise
    for a first joint that slides or an arm of one joint."""
    reach = arm_reach(model, arm, fixed)
    rest = arm.joints[len(lift_joints(model, arm)) :]
    if len(rest) < 2 or model.joints[rest[0]].type == "prismatic":
        return ArmRise((0.0, 0.0, 0.0), reach)
    held = dict(fixed or {})
    first, second = model.joints[rest[0]], model.joints[rest[1]]
    frame = link_pose(model, first.parent, held) * first.origin
    start = np.asarray(frame.position)
    end = np.asarray((link_pose(model, second.parent, held) * second.origin).position)
    axis = np.asarray(first.axis, dtype=float)
    axis = np.asarray((Pose(orientation=frame.orientation) * Pose(tuple(axis))).position)
    axis /= np.linalg.norm(axis)
    segment = end - start
    along = float(segment @ axis)
    across = float(np.linalg.norm(segment - along * axis))
    rise = tuple(float(v) for v in along * axis)
    return ArmRise(rise, reach - math.dist(start, end) + across)  # type: ignore[arg-type]

"""The limits a trajectory must respect, per joint: position, velocity, acceleration, jerk.

Position and velocity limits come from the URDF; acceleration limits from the
description's ``acceleration_limits`` (URDFs have none), else a default per joint kind.
Jerk limits (ruckig needs them) are a fixed multiple of the acceleration limit.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from robocram.motion.errors import MotionError
from robocram.robots import LoadedDescription

DEFAULT_VELOCITY = 0.5  # [rad/s | m/s] for joints whose URDF gives no velocity limit
DEFAULT_ACCELERATION = {"revolute": 1.5, "continuous": 1.5, "prismatic": 0.5}  # [/s^2]
JERK_PER_ACCELERATION = 10.0  # [1/s] jerk limit = this x acceleration limit
BASE_LIMITS = {  # the planar base's joints x, y [m], yaw [rad]; a flying body's z, roll, pitch
    "x": (0.5, 0.5),  # velocity [m/s], acceleration [m/s^2]
    "y": (0.5, 0.5),
    "z": (0.5, 0.5),
    "roll": (1.0, 1.0),  # [rad/s], [rad/s^2]
    "pitch": (1.0, 1.0),
    "yaw": (1.0, 1.0),
}


@dataclass(frozen=True)
class JointLimits:
    """One joint's limits; ``lower``/``upper`` are +-inf for continuous joints."""

    name: str
    lower: float  # [rad | m]
    upper: float
    velocity: float  # [rad/s | m/s]
    acceleration: float  # [rad/s^2 | m/s^2]
    jerk: float  # [rad/s^3 | m/s^3]


def joint_limits(desc: LoadedDescription, joints: Sequence[str]) -> tuple[JointLimits, ...]:
    """The limits of ``joints`` of ``desc``'s robot, in that order.

    Raises:
        MotionError: a joint is not a movable joint of the robot (named, with the fix).
    """
    found = []
    for name in joints:
        named = desc.model.joints.get(name)
        if name in BASE_LIMITS and (named is None or not named.movable):  # a URDF's own first
            velocity, acceleration = BASE_LIMITS[name]
            found.append(
                JointLimits(
                    name, -math.inf, math.inf, velocity, acceleration,
                    JERK_PER_ACCELERATION * acceleration,
                )
            )  # fmt: skip
            continue
        joint = desc.model.joints.get(name)
        if joint is None or not joint.movable:
            raise MotionError(
                f"{name!r} is not a movable joint of {desc.name}; trajectories take the "
                "names of its revolute, continuous or prismatic joints"
            )
        acceleration = desc.acceleration_limits.get(
            name, DEFAULT_ACCELERATION.get(str(joint.type), 1.0)
        )
        lower = joint.lower if joint.lower is not None else -math.inf
        upper = joint.upper if joint.upper is not None else math.inf
        velocity = joint.velocity or DEFAULT_VELOCITY
        found.append(
            JointLimits(
                name, lower, upper, velocity, acceleration, JERK_PER_ACCELERATION * acceleration
            )
        )
    return tuple(found)

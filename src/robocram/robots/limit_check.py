"""The limits a robot description gives its joints, checked when it loads.

The URDF's velocity and effort (the URDF standard and pinocchio need both on a revolute
or prismatic joint) and the description's acceleration limits must be rates a trajectory
can be timed under: ruckig fails on limits of 1e-300 (and of 1e300), and a trajectory's
samples grow with the inverse of the limit.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from robocram.robots.errors import LimitValueError, UrdfError
from robocram.robots.robot_model import RobotModel

MIN_RATE_LIMIT = 1e-6  # [/s | /s^2] the smallest velocity or acceleration limit taken
_RATES = {"velocity": "speed [rad/s | m/s]", "effort": "effort [N m | N]"}


def check_rate_limits(model: RobotModel) -> None:
    """Refuse a revolute or prismatic joint whose URDF ``<limit>`` lacks velocity or effort,
    or whose velocity limit is below :data:`MIN_RATE_LIMIT` (0 stands for "none given").

    The URDF standard requires both, and the robot's kinematics (pinocchio) refuses the
    model without them: every arm motion would fail there, far from the cause.

    Raises:
        UrdfError: naming the first such joint and what to add.
    """
    for joint in model.joints.values():
        if joint.type not in ("revolute", "prismatic"):
            continue
        for key, what in _RATES.items():
            if getattr(joint, key) is None:
                raise UrdfError(
                    model.source,
                    f"{joint.type} joint {joint.name!r} has no {key} limit; give its largest "
                    f"{what} in its <limit {key}=...> (the URDF standard and pinocchio "
                    "require it)",
                )
        if joint.velocity is not None and 0.0 < joint.velocity < MIN_RATE_LIMIT:
            raise UrdfError(
                model.source,
                f"{joint.type} joint {joint.name!r} has velocity limit {joint.velocity}, below "
                f"{MIN_RATE_LIMIT:g} (MIN_RATE_LIMIT); give its real largest speed",
            )


def check_acceleration_limits(robot_name: str, limits: Mapping[str, float]) -> None:
    """Raise :class:`LimitValueError` for an acceleration limit that is not a finite
    number of at least :data:`MIN_RATE_LIMIT` (0, negative, NaN, inf, 1e-300)."""
    for name, value in limits.items():
        if not (math.isfinite(value) and value >= MIN_RATE_LIMIT):
            raise LimitValueError(
                robot_name, name, "acceleration limit [/s^2]", value, MIN_RATE_LIMIT
            )

"""Mimic joints: a follower joint's value is ``multiplier * master + offset``.

Everyone who sets joint values (the world, IK, the projected robot) expands them with
:func:`mimic_followers` so a gripper's fingers or a telescoping torso move together.
"""

from __future__ import annotations

from collections.abc import Mapping

from robocram.robots.errors import DescriptionError
from robocram.robots.robot_model import RobotModel

_CONSISTENT = 1e-9  # [rad | m] a follower given with its master must match within this


def mimic_followers(model: RobotModel, values: Mapping[str, float]) -> dict[str, float]:
    """``values`` plus the value of every mimic joint that follows one of them, transitively.

    A follower given together with its master must agree with it; a follower given alone
    is kept as is. Unknown joint names raise a :class:`DescriptionError` with suggestions.
    """
    for name in values:
        model.joint(name)
    result = dict(values)
    changed = True
    while changed:
        changed = False
        for joint in model.joints.values():
            mimic = joint.mimic
            if mimic is None or mimic.joint not in result:
                continue
            value = mimic.multiplier * result[mimic.joint] + mimic.offset
            if joint.name in values and abs(values[joint.name] - value) > _CONSISTENT:
                raise DescriptionError(
                    f"joint {joint.name!r} mimics {mimic.joint!r} and must be {value}, "
                    f"got {values[joint.name]}; set only the master {mimic.joint!r}"
                )
            if joint.name not in result:
                result[joint.name] = value
                changed = True
    return result

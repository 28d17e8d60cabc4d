"""Mimic joints: a follower joint's value is ``multiplier * master + offset``.

Everyone who sets joint values (the world, IK, the projected robot) expands them with
:func:`mimic_followers` so a gripper's fingers or a telescoping torso move together.
"""

from __future__ import annotations

from collections.abc import Mapping

from robocram.robots.errors import DescriptionError
from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Joint, Mimic

_CONSISTENT = 1e-9  # [rad | m] a follower given with its master must match within this


def mimic_followers(model: RobotModel, values: Mapping[str, float]) -> dict[str, float]:
    """``values`` plus the value of every mimic joint that follows one of them, transitively.

    A follower given together with its master must agree with it; a follower given alone
    is kept as is. Unknown joint names raise a :class:`DescriptionError` with suggestions.
    """
    for name in values:
        model.joint(name)
    result = dict(values)
    followers = model.derived(_mimic_joints)
    changed = bool(followers)
    while changed:
        changed = False
        for joint, mimic in followers:
            if mimic.joint not in result:
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


def _mimic_joints(model: RobotModel) -> tuple[tuple[Joint, Mimic], ...]:
    """The model's mimic joints with their mimic, in the model's joint order: the walk
    above visits only these (the others never follow anything), in the order it would
    visit them among all joints, so the result and its order are the same. Kept with the
    model (``RobotModel.derived``): models never change."""
    return tuple((j, j.mimic) for j in model.joints.values() if j.mimic is not None)

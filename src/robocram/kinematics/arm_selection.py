"""Which joints and frame an IK query for a named arm of a description moves."""

from __future__ import annotations

from robocram.kinematics.errors import KinematicsError, UnknownNameError
from robocram.robots import ArmDescription, RobotDescription, RobotModel, load_description


def loaded(description: RobotDescription | str) -> tuple[RobotDescription, RobotModel]:
    """The description and its model: built-in names and unloaded descriptions get loaded.

    Each load makes a new model, with nothing kept yet: callers asking more than once pass
    the loaded description, whose model keeps the solvers built for it.
    """
    desc = description
    if isinstance(desc, str) or desc.model is None:
        desc = load_description(desc)
    if desc.model is None:
        raise KinematicsError(f"description {desc.name!r} has no model after loading")
    return desc, desc.model


def arm_description(desc: RobotDescription, arm: str) -> ArmDescription:
    """``desc.arms[arm]``, or an error naming the arms the robot has."""
    spec = desc.arms.get(arm)
    if spec is None:
        raise UnknownNameError("arm", arm, desc.name, desc.arms)
    return spec


def arm_joints(description: RobotDescription, arm: str, use_torso: bool = False) -> tuple[str, ...]:
    """The joints IK for ``arm`` may move: the arm's, after the torso joint if allowed."""
    desc, model = loaded(description)
    spec = arm_description(desc, arm)
    joints = spec.joints
    if not joints:
        start = spec.base_link or model.root_link
        joints = tuple(j.name for j in model.chain(start, spec.end_effector_link) if j.movable)
    if use_torso:
        if desc.torso_joint is None:
            raise KinematicsError(
                f"{desc.name} has no torso joint (description.torso_joint is None); "
                "call solve_ik with use_torso=False"
            )
        joints = (desc.torso_joint, *joints)
    return joints

"""What each joint of an arm does, read from the chain's kinematics, not its position.

- **lift**: the leading joints that slide vertically (Stretch's ``joint_lift``);
- **telescope**: the joints after the lift that slide, coupled followers included
  (Stretch's ``joint_arm_l3`` to ``joint_arm_l0``);
- **wrist**: the turning joints after the last sliding one whose axes pass within
  :data:`WRIST_RADIUS` of the end effector: they orient the hand more than they move it;
- **fingers**: the gripper's joints.

A joint may have none of these roles (a shoulder or an elbow).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from robocram.robots.arm_envelope import lift_joints
from robocram.robots.description import ArmDescription
from robocram.robots.model_pose import link_pose
from robocram.robots.robot_model import RobotModel

WRIST_RADIUS = 0.15  # [m] from a joint's origin to the end effector, at zero, for a wrist


@dataclass(frozen=True)
class ArmRoles:
    """Joint names by role, in chain order (see the module docstring)."""

    lift: tuple[str, ...]
    telescope: tuple[str, ...]
    wrist: tuple[str, ...]
    fingers: tuple[str, ...]


def arm_roles(model: RobotModel, arm: ArmDescription) -> ArmRoles:
    """The roles of the joints of a loaded ``arm`` (its joints and gripper set)."""
    start = arm.base_link or model.joints[arm.joints[0]].parent
    chain = [j for j in model.chain(start, arm.end_effector_link) if j.movable]
    lift = lift_joints(model, arm)
    rest = [j for j in chain if j.name not in lift]
    telescope = tuple(j.name for j in rest if j.type == "prismatic")
    last = max((i for i, j in enumerate(rest) if j.type == "prismatic"), default=-1)
    hand = link_pose(model, arm.end_effector_link).position
    wrist = tuple(
        j.name
        for j in rest[last + 1 :]
        if math.dist((link_pose(model, j.parent) * j.origin).position, hand) <= WRIST_RADIUS
    )
    fingers = arm.gripper_joints or (arm.gripper.names if arm.gripper is not None else ())
    return ArmRoles(lift, telescope, wrist, tuple(fingers))

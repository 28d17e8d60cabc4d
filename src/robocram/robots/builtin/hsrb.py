"""The Toyota HSR-B, from robocram's own simple-shape URDF with the robot's real kinematics.

One arm, named ``arm`` (CRAM had to fake it as ``:left`` plus a dummy ``:right``). The torso
joint is ``arm_lift_joint``: raising it lifts the arm by the full amount and, through the
mimic ``torso_lift_joint = 0.5 * arm_lift_joint``, the head and its camera by half of it.
Choosing ``torso_lift_joint`` instead would name a follower no one can command. The arm
chain starts after the lift (``arm_lift_link``), so IK that may move the torso adds
``arm_lift_joint`` itself.

The original has no tool frame between the fingers; ``hand_tool_frame`` is added in code,
8 cm in front of the palm, with the PR2's tool-frame convention: x along the approach
direction (out of the palm), y along which the fingers open.
"""

from __future__ import annotations

import math
from pathlib import Path

from robocram.robots.description import (
    ArmDescription,
    CameraDescription,
    FrameSpec,
    PanTiltDescription,
    RobotDescription,
)
from robocram.tf import Pose

URDF = Path(__file__).resolve().parents[1] / "data" / "hsrb.urdf"
TOOL_FRAME_OFFSET = 0.08  # [m] in front of hand_palm_link, between the finger tips' reach
_ARM_JOINTS = ("arm_flex_joint", "arm_roll_joint", "wrist_flex_joint", "wrist_roll_joint")
_FINGER_LINKS = tuple(
    f"hand_{side}_{part}_link"
    for side in ("l", "r")
    for part in ("proximal", "spring_proximal", "mimic_distal", "distal")
)
# Arm folded in front of the body, hand pointing to the right: HSR's usual driving pose.
_PARKING = (0.0, -1.57, -1.57, 0.0)
# Forearm forward and level (arm_flex + wrist_flex = -pi/2): holds an object while driving.
_CARRYING = (-0.5, 0.0, -1.07, 0.0)
_XTION_HFOV = math.radians(58.0)  # [rad] the Xtion PRO LIVE's RGB field of view
_XTION_VFOV = math.radians(45.0)  # [rad]


def _arm() -> ArmDescription:
    return ArmDescription(
        name="arm",
        end_effector_link="hand_palm_link",
        tool_frame="hand_tool_frame",
        base_link="arm_lift_link",
        joints=_ARM_JOINTS,
        gripper_joints=("hand_motor_joint",),
        gripper_links=_FINGER_LINKS,
        hand_links=("hand_palm_link", *_FINGER_LINKS),
        parking=dict(zip(_ARM_JOINTS, _PARKING, strict=True)),
        carrying=dict(zip(_ARM_JOINTS, _CARRYING, strict=True)),
    )


def description() -> RobotDescription:
    """The HSR-B's description (unchecked; ``load_description("hsrb")`` checks it)."""
    return RobotDescription(
        name="hsrb",
        urdf=URDF,
        base_frame="base_footprint",
        odom_frame="odom",
        torso_link="arm_lift_link",
        torso_joint="arm_lift_joint",
        arms={"arm": _arm()},
        cameras=(
            CameraDescription(  # heights derived: 0.967 m to 1.312 m as the torso lifts it
                frame="head_rgbd_sensor_link",
                horizontal_fov=_XTION_HFOV,
                vertical_fov=_XTION_VFOV,
                name="head_rgbd_sensor",
            ),
        ),
        pan_tilt=PanTiltDescription(
            pan_link="head_pan_link",
            tilt_link="head_tilt_link",
            pan_joint="head_pan_joint",
            tilt_joint="head_tilt_joint",
        ),
        neck_parking={"head_pan_joint": 0.0, "head_tilt_joint": 0.0},
        extra_frames=(
            FrameSpec(
                name="hand_tool_frame",
                parent="hand_palm_link",
                pose=Pose.from_xyz_rpy((0.0, 0.0, TOOL_FRAME_OFFSET), (0.0, -math.pi / 2, 0.0)),
            ),
        ),
    )

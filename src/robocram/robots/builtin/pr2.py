"""The PR2, from the URDF and meshes of the PyPI package ``example-robot-data``.

Two arms, ``left`` and ``right``, each with a parallel gripper whose finger joints mimic
``<side>_gripper_l_finger_joint``; a pan-tilt head with the wide stereo camera (640 x 480,
90 degrees horizontal field of view in the URDF's sensor tag).
"""

from __future__ import annotations

import math

from robocram.robots.description import (
    ArmDescription,
    CameraDescription,
    PanTiltDescription,
    RobotDescription,
)
from robocram.robots.example_robot_data import example_robot_data_folder

_ARM_JOINTS = (
    "shoulder_pan_joint",
    "shoulder_lift_joint",
    "upper_arm_roll_joint",
    "elbow_flex_joint",
    "forearm_roll_joint",
    "wrist_flex_joint",
    "wrist_roll_joint",
)
_GRIPPER_LINKS = (
    "gripper_palm_link",
    "gripper_l_finger_link",
    "gripper_r_finger_link",
    "gripper_l_finger_tip_link",
    "gripper_r_finger_tip_link",
)
# Arms folded beside the torso, out of the way for driving; the left arm mirrors the right.
# CRAM's values; the wrist flex (-0.07) lies beyond its soft upper limit (-0.1), where the
# real PR2 stops it, so over ROS parking is sent with -0.1 (ros/motion_planner.clamp_goal).
_RIGHT_PARKING = (-1.712, -0.256, -1.463, -2.12, 1.766, -0.07, 0.051)
# Hand in front of the chest, wrist level: holds an object while the base moves.
_RIGHT_CARRYING = (-0.5, 0.0, -0.3, -1.8, 0.0, -0.3, 0.0)
# Mirroring across the sagittal plane flips the sign of joints about x and z axes.
_MIRROR = (-1, 1, -1, 1, -1, 1, -1)

_WIDE_STEREO_HFOV = math.radians(90.0)  # [rad] from the URDF's <hfov>90</hfov>
_WIDE_STEREO_VFOV = 2 * math.atan(math.tan(_WIDE_STEREO_HFOV / 2) * 480 / 640)  # [rad]


def _arm(side: str) -> ArmDescription:
    prefix = side[0]
    joints = tuple(f"{prefix}_{j}" for j in _ARM_JOINTS)
    sign = (1,) * 7 if side == "right" else _MIRROR
    parking = {j: s * v for j, s, v in zip(joints, sign, _RIGHT_PARKING, strict=True)}
    carrying = {j: s * v for j, s, v in zip(joints, sign, _RIGHT_CARRYING, strict=True)}
    gripper_links = tuple(f"{prefix}_{link}" for link in _GRIPPER_LINKS)
    return ArmDescription(
        name=side,
        end_effector_link=f"{prefix}_wrist_roll_link",
        tool_frame=f"{prefix}_gripper_tool_frame",
        base_link="torso_lift_link",
        joints=joints,
        gripper_joints=(f"{prefix}_gripper_l_finger_joint",),
        gripper_links=gripper_links,
        hand_links=gripper_links,
        parking=parking,
        carrying=carrying,
    )


def description() -> RobotDescription:
    """The PR2's description (unchecked; ``load_description("pr2")`` checks it)."""
    return RobotDescription(
        name="pr2",
        urdf=example_robot_data_folder() / "pr2_description" / "urdf" / "pr2.urdf",
        base_frame="base_footprint",
        odom_frame="odom_combined",
        torso_link="torso_lift_link",
        torso_joint="torso_lift_joint",
        arms={"left": _arm("left"), "right": _arm("right")},
        cameras=(
            CameraDescription(
                frame="wide_stereo_optical_frame",
                minimal_height=1.27,  # [m] torso down, head level
                maximal_height=1.58,  # [m] torso up by 0.31 m
                horizontal_fov=_WIDE_STEREO_HFOV,
                vertical_fov=_WIDE_STEREO_VFOV,
                name="wide_stereo",
            ),
        ),
        pan_tilt=PanTiltDescription(
            pan_link="head_pan_link",
            tilt_link="head_tilt_link",
            pan_joint="head_pan_joint",
            tilt_joint="head_tilt_joint",
        ),
        neck_parking={"head_pan_joint": 0.0, "head_tilt_joint": 0.0},
    )

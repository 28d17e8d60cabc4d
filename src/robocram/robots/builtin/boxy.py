"""IAI's Boxy, from robocram's own simple-shape URDF with the robot's real kinematics.

Two KUKA LWR4+ arms, ``left`` and ``right``, hang from a carriage (``triangle_base_link``)
that the prismatic torso joint ``triangle_base_joint`` lowers by up to 0.586 m. Each arm
ends in a WSG-50 gripper whose master joint ``<side>_gripper_joint`` is the finger opening
[m]; the other finger joint mimics it. The camera is a Kinect2 on a UR3 neck, described as a
third arm ``neck`` (``neck_arm``), so looking is reaching with the camera's optical frame.

The robot's own ``<side>_gripper_tool_frame`` has z along the approach direction and x along
which the fingers open. Plans are robot-independent only if every tool frame follows one
convention (PR2's: x approach, y opening, CRAM's "standard gripper"), so the arms' tool frame
is ``<side>_standard_gripper_tool_frame``, added in code on top of the real one.
"""

from __future__ import annotations

import math
from pathlib import Path

from robocram.robots.description import (
    ArmDescription,
    CameraDescription,
    FrameSpec,
    RobotDescription,
)
from robocram.tf import Pose

URDF = Path(__file__).resolve().parents[1] / "data" / "boxy.urdf"
CAMERA_FRAME = "head_mount_kinect2_rgb_optical_frame"
_NECK_JOINTS = (
    "neck_shoulder_pan_joint",
    "neck_shoulder_lift_joint",
    "neck_elbow_joint",
    "neck_wrist_1_joint",
    "neck_wrist_2_joint",
    "neck_wrist_3_joint",
)
# Kinect2 at (0.62, 0.04, 1.75) m over base_footprint, looking straight ahead and 40 degrees
# down at the workspace in front of the robot, image x to the robot's right.
_NECK_PARKING = (1.431, 0.388, 2.359, -0.467, -1.493, 0.107)
# Grippers pointing down beside the base at (0.6, 0.45 | -0.36, 0.9) m over base_footprint
# with the torso up, mirrored across the arms' middle plane y = 0.045 m.
_PARKING = {
    "left": (-0.379, 0.91, 0.566, -1.648, 0.589, 0.909, 0.414),
    "right": (-0.797, -0.651, 0.135, 1.683, 0.455, -0.818, 1.021),
}
# The Kinect2's full-HD colour camera.
_KINECT2_HFOV = math.radians(84.1)  # [rad]
_KINECT2_VFOV = math.radians(53.8)  # [rad]
# Camera heights over the floor the neck reaches with the view ahead and 40 degrees down,
# near the workspace (x = 0.62 m); the neck is fixed to the base, the torso does not move it.
_CAMERA_LOWEST = 1.45  # [m]
_CAMERA_HIGHEST = 2.0  # [m]
# Axes of the standard gripper frame in Boxy's tool frame: x' = z (approach), y' = x (opening).
_STANDARD_FROM_BOXY_TOOL = Pose((0.0, 0.0, 0.0), (0.5, 0.5, 0.5, -0.5))


def standard_tool_frame(side: str) -> FrameSpec:
    """The PR2-convention tool frame of one arm, on top of Boxy's own tool frame."""
    return FrameSpec(
        name=f"{side}_standard_gripper_tool_frame",
        parent=f"{side}_gripper_tool_frame",
        pose=_STANDARD_FROM_BOXY_TOOL,
    )


def _arm(side: str) -> ArmDescription:
    joints = tuple(f"{side}_arm_{i}_joint" for i in range(7))
    gripper = f"{side}_gripper"
    finger_links = tuple(
        f"{gripper}_{part}_link"
        for part in ("gripper_left", "finger_left", "gripper_right", "finger_right")
    )
    return ArmDescription(
        name=side,
        end_effector_link=f"{side}_arm_7_link",
        tool_frame=f"{side}_standard_gripper_tool_frame",
        base_link=f"calib_{side}_arm_base_link",
        joints=joints,
        gripper_joints=(f"{gripper}_joint",),
        gripper_links=finger_links,
        hand_links=(f"{side}_arm_flange_link", f"{gripper}_base_link", *finger_links),
        parking=dict(zip(joints, _PARKING[side], strict=True)),
    )


def _neck() -> ArmDescription:
    return ArmDescription(
        name="neck",
        end_effector_link="neck_wrist_3_link",
        tool_frame=CAMERA_FRAME,
        base_link="neck_base_link",
        joints=_NECK_JOINTS,
        parking=dict(zip(_NECK_JOINTS, _NECK_PARKING, strict=True)),
    )


def description() -> RobotDescription:
    """Boxy's description (unchecked; ``load_description("boxy")`` checks it)."""
    return RobotDescription(
        name="boxy",
        urdf=URDF,
        base_frame="base_footprint",
        odom_frame="odom",
        torso_link="triangle_base_link",
        torso_joint="triangle_base_joint",
        arms={"left": _arm("left"), "right": _arm("right"), "neck": _neck()},
        cameras=(
            CameraDescription(
                frame=CAMERA_FRAME,
                minimal_height=_CAMERA_LOWEST,
                maximal_height=_CAMERA_HIGHEST,
                horizontal_fov=_KINECT2_HFOV,
                vertical_fov=_KINECT2_VFOV,
                name="kinect2",
            ),
        ),
        neck_arm="neck",
        extra_frames=(standard_tool_frame("left"), standard_tool_frame("right")),
        neck_parking=dict(zip(_NECK_JOINTS, _NECK_PARKING, strict=True)),
    )

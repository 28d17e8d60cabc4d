"""stretch_description: a robot description drafted by `robocram robot draft`
from stretch_description.urdf.

Check it with `robocram robot check stretch.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

import math
from pathlib import Path

from robocram.robots import (
    ArmDescription,
    CameraDescription,
    JointCoupling,
    PanTiltDescription,
    RobotDescription,
)

URDF = Path(__file__).resolve().parent / "stretch_description/urdf/stretch_description.urdf"


def description() -> RobotDescription:
    """The stretch_description description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="stretch_description",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="base_link",
        # why: joint_right_wheel and joint_left_wheel drive two wheels on one axle: no sideways
        #   motion
        base_type="differential",
        # why: one gripper-like end
        arms={
            "arm": ArmDescription(
                name="arm",
                # why: child of joint_wrist_roll, the last joint before the fingers
                end_effector_link="link_wrist_roll",
                # why: the URDF's frame at the fingers, x = approach
                tool_frame="link_grasp_center",
                # why: parent of the first arm joint; its joints down to the wrist are found at load
                base_link="link_mast",
                # why: joint_lift lifts this arm only, not the camera: its first joint; joint_arm_l3
                #   drives the telescope (coupled_joints)
                joints=(
                    "joint_lift",
                    "joint_arm_l3",
                    "joint_wrist_yaw",
                    "joint_wrist_pitch",
                    "joint_wrist_roll",
                ),
                # why: the finger joints (prismatic, or leaves) right below the wrist; fingers and
                #   hand links are found at load
                gripper_joints=("joint_gripper_finger_right", "joint_gripper_finger_left"),
                # why: stowed: within limits, the telescope retracted, the arm within 0.26 m of the
                #   base's middle (the sampled pose: touching), 1 cm clear of its other links
                #   (meshes)
                parking={
                    "joint_lift": 0.175,
                    "joint_arm_l3": 0.0,
                    "joint_wrist_yaw": 2.192,
                    "joint_wrist_pitch": -0.48,
                    "joint_wrist_roll": 0.426,
                },
            ),
        },
        # why: camera frame by name (8 found, best first); optical: z looks forward; others:
        #   camera_gyro_optical_frame, camera_accel_optical_frame, camera_color_frame
        cameras=(
            CameraDescription(
                # why: heights 1.322 to 1.322 m over the base (torso at its limits) are derived at
                #   load; give minimal_height and maximal_height to override
                frame="camera_color_optical_frame",
                # TODO doubt: the URDF gives no field of view: take the sensor's
                horizontal_fov=math.radians(60),
                vertical_fov=math.radians(45),
            ),
        ),
        # why: two joints turn the camera: the first pans, the second tilts
        pan_tilt=PanTiltDescription(pan_joint="joint_head_pan", tilt_joint="joint_head_tilt"),
        # why: head at zero: straight ahead
        neck_parking={"joint_head_pan": 0.0, "joint_head_tilt": 0.0},
        # why: 4 prismatic joints in a row sliding along one axis with equal limits: a telescope,
        #   moved by one actuator
        coupled_joints=(
            JointCoupling(
                actuator="joint_arm_l3", followers=("joint_arm_l2", "joint_arm_l1", "joint_arm_l0")
            ),
        ),
    )

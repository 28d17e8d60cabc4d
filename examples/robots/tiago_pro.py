"""tiago_pro: a robot description drafted by `robocram robot draft` from tiago_pro.urdf.

Check it with `robocram robot check tiago_pro.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

from robocram.robots import (
    ArmDescription,
    CameraDescription,
    FrameSpec,
    GripperDescription,
    GripperJoint,
    PanTiltDescription,
    RobotDescription,
    example_robot_data_folder,
)
from robocram.tf import Pose

URDF = example_robot_data_folder() / "tiago_pro_description/robots/tiago_pro.urdf"


def description() -> RobotDescription:
    """The tiago_pro description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="tiago_pro",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="base_footprint",
        # why: 4 wheels on fixed axles (wheel_front_right_joint, wheel_front_left_joint,
        #   wheel_rear_right_joint, wheel_rear_left_joint): mecanum wheels drive any way
        # TODO doubt: skid-steered wheels would not: then say base_type='differential'
        base_type="holonomic",
        # why: vertical prismatic joint carrying 3 of the arms and cameras
        torso_joint="torso_lift_joint",
        # why: two alike arms 0.882 m apart (left: larger y)
        arms={
            "left": ArmDescription(
                name="left",
                # why: child of arm_left_7_joint, the last joint before the fingers
                end_effector_link="arm_left_7_link",
                # why: no frame of the URDF reaches the fingers: added 0.163 m out along the
                #   approach, amid the outer half of the closed fingers
                tool_frame="left_standard_tool_frame",
                # why: parent of the first arm joint after the torso; its joints down to the wrist
                #   are found at load
                base_link="torso_lift_link",
                # why: sampled in limits (seed 0): wrist low beside the shoulder, out of view
                # TODO doubt: its links touch (arm_left_5_link/arm_left_7_link,
                #   arm_left_5_link/gripper_left_base_link) and no stowed pose was found: give one
                parking={
                    "arm_left_1_joint": -0.112,
                    "arm_left_2_joint": -2.192,
                    "arm_left_3_joint": -0.737,
                    "arm_left_4_joint": -2.338,
                    "arm_left_5_joint": -2.094,
                    "arm_left_6_joint": -1.86,
                    "arm_left_7_joint": 2.484,
                },
                # why: mimicked by 5 hand joint(s) (<mimic> in the URDF); open at the lower limit,
                #   where the fingers part
                gripper=GripperDescription(
                    (GripperJoint("gripper_left_finger_joint", open=0.0, closed=0.802851),)
                ),
            ),
            "right": ArmDescription(
                name="right",
                # why: child of arm_right_7_joint, the last joint before the fingers
                end_effector_link="arm_right_7_link",
                # why: no frame of the URDF reaches the fingers: added 0.163 m out along the
                #   approach, amid the outer half of the closed fingers
                tool_frame="right_standard_tool_frame",
                # why: parent of the first arm joint after the torso; its joints down to the wrist
                #   are found at load
                base_link="torso_lift_link",
                # why: sampled in limits (seed 0): wrist low beside the shoulder, out of view
                # TODO doubt: its links touch () and no stowed pose was found: give one
                parking={
                    "arm_right_1_joint": -1.42,
                    "arm_right_2_joint": -0.516,
                    "arm_right_3_joint": -2.031,
                    "arm_right_4_joint": -2.072,
                    "arm_right_5_joint": -0.175,
                    "arm_right_6_joint": -0.496,
                    "arm_right_7_joint": -1.656,
                },
                # why: mimicked by 5 hand joint(s) (<mimic> in the URDF); open at the lower limit,
                #   where the fingers part
                gripper=GripperDescription(
                    (GripperJoint("gripper_right_finger_joint", open=0.0, closed=0.802851),)
                ),
            ),
        },
        # why: camera frame by name (2 found, best first); its x looks forward (body convention):
        #   optical frame added, z forward; others: head_front_camera_bottom_screw_frame
        cameras=(
            CameraDescription(
                # why: heights 1.160 to 1.510 m over the base (torso at its limits) are derived at
                #   load; give minimal_height and maximal_height to override
                frame="head_front_camera_link_optical",
                # why: the URDF's Gazebo sensor 'head_front_cameracolor' on head_front_camera_link
                #   at 640 x 480 pixels
                horizontal_fov=1.2113,
                vertical_fov=0.958,
            ),
        ),
        # why: two joints turn the camera: the first pans, the second tilts
        pan_tilt=PanTiltDescription(pan_joint="head_1_joint", tilt_joint="head_2_joint"),
        # why: head at zero: straight ahead
        neck_parking={"head_1_joint": 0.0, "head_2_joint": 0.0},
        extra_frames=(
            FrameSpec(
                name="left_standard_tool_frame",
                parent="arm_left_7_link",
                pose=Pose((0.0, 0.0, 0.163436), (0.0, -0.707107, 0.0, 0.707107)),
            ),
            FrameSpec(
                name="right_standard_tool_frame",
                parent="arm_right_7_link",
                pose=Pose((0.0, 0.0, 0.163436), (0.707107, 0.0, 0.707107, 0.0)),
            ),
            FrameSpec(
                name="head_front_camera_link_optical",
                parent="head_front_camera_link",
                pose=Pose((0.0, 0.0, 0.0), (-0.5, 0.5, -0.5, 0.5)),
            ),
        ),
    )

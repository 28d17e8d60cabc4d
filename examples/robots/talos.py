"""talos: a robot description drafted by `robocram robot draft` from talos_full_v2.urdf.

Check it with `robocram robot check talos.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

from robocram.robots import (
    ArmDescription,
    CameraDescription,
    FrameSpec,
    PanTiltDescription,
    RobotDescription,
    example_robot_data_folder,
)
from robocram.tf import Pose

URDF = example_robot_data_folder() / "talos_data/robots/talos_full_v2.urdf"


def description() -> RobotDescription:
    """The talos description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="talos",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="base_link",
        # why: no driven wheels in the URDF: the default
        # TODO doubt: holonomic assumed; say 'differential' for two wheels on one axle, 'fixed' for
        #   a base that stays
        base_type="holonomic",
        # why: two alike arms 0.588 m apart (left: larger y); below the trunk that turns them all
        #   (torso_1_joint, torso_2_joint)
        arms={
            "left": ArmDescription(
                name="left",
                # why: child of arm_left_7_joint, the last joint before the fingers
                end_effector_link="arm_left_7_link",
                # why: no frame of the URDF reaches the fingers: added 0.215 m out along the
                #   approach, amid the outer half of the closed fingers
                tool_frame="left_standard_tool_frame",
                # why: parent of the first arm joint after the torso; its joints down to the wrist
                #   are found at load
                base_link="torso_2_link",
                # why: mimicked by 6 hand joint(s) (<mimic> in the URDF); fingers and hand links are
                #   found at load
                gripper_joints=("gripper_left_joint",),
                # why: sampled in limits (seed 0): wrist low beside the shoulder, out of view
                # TODO doubt: its links touch (arm_left_3_link/arm_left_5_link) and no stowed pose
                #   was found: give one
                parking={
                    "arm_left_1_joint": 0.785,
                    "arm_left_2_joint": 0.804,
                    "arm_left_3_joint": -0.507,
                    "arm_left_4_joint": -2.234,
                    "arm_left_5_joint": -1.818,
                    "arm_left_6_joint": 1.011,
                    "arm_left_7_joint": 0.019,
                },
            ),
            "right": ArmDescription(
                name="right",
                # why: child of arm_right_7_joint, the last joint before the fingers
                end_effector_link="arm_right_7_link",
                # why: no frame of the URDF reaches the fingers: added 0.215 m out along the
                #   approach, amid the outer half of the closed fingers
                tool_frame="right_standard_tool_frame",
                # why: parent of the first arm joint after the torso; its joints down to the wrist
                #   are found at load
                base_link="torso_2_link",
                # why: mimicked by 6 hand joint(s) (<mimic> in the URDF); fingers and hand links are
                #   found at load
                gripper_joints=("gripper_right_joint",),
                # why: sampled in limits (seed 0): wrist low beside the shoulder, out of view
                # TODO doubt: its links touch (arm_right_3_link/arm_right_5_link) and no stowed pose
                #   was found: give one
                parking={
                    "arm_right_1_joint": -0.785,
                    "arm_right_2_joint": -0.777,
                    "arm_right_3_joint": 0.422,
                    "arm_right_4_joint": -2.234,
                    "arm_right_5_joint": -1.771,
                    "arm_right_6_joint": 0.457,
                    "arm_right_7_joint": -0.181,
                },
            ),
        },
        # why: camera frame by name (4 found, best first); optical: z looks forward; others:
        #   rgbd_rgb_optical_frame, rgbd_link, rgbd_rgb_frame
        cameras=(
            CameraDescription(
                # why: heights 0.591 to 0.591 m over the base (torso at its limits) are derived at
                #   load; give minimal_height and maximal_height to override
                frame="rgbd_optical_frame",
                # why: the URDF's Gazebo sensor 'rgbd_frame_sensor' on rgbd_link at 640 x 480 pixels
                horizontal_fov=1.0472,
                vertical_fov=0.8173,
            ),
        ),
        # why: two joints turn the camera: the first tilts (horizontal axis), the second pans
        pan_tilt=PanTiltDescription(pan_joint="head_2_joint", tilt_joint="head_1_joint"),
        # why: head at zero: straight ahead
        neck_parking={"head_2_joint": 0.0, "head_1_joint": 0.0},
        extra_frames=(
            FrameSpec(
                name="left_standard_tool_frame",
                parent="arm_left_7_link",
                pose=Pose((0.0, -0.003158, -0.215289), (0.0, 0.707107, 0.0, 0.707107)),
            ),
            FrameSpec(
                name="right_standard_tool_frame",
                parent="arm_right_7_link",
                pose=Pose((0.0, 0.003158, -0.215289), (-0.707107, 0.0, 0.707107, 0.0)),
            ),
        ),
    )

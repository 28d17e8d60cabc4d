"""tiago: a robot description drafted by `robocram robot draft` from tiago.urdf.

Check it with `robocram robot check tiago.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

from robocram.robots import (
    ArmDescription,
    CameraDescription,
    FrameSpec,
    GripperDescription,
    PanTiltDescription,
    RobotDescription,
    example_robot_data_folder,
)
from robocram.tf import Pose

URDF = example_robot_data_folder() / "tiago_description/robots/tiago.urdf"


def description() -> RobotDescription:
    """The tiago description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="tiago",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="base_footprint",
        # why: wheel_right_joint and wheel_left_joint drive two wheels on one axle: no sideways
        #   motion
        base_type="differential",
        # why: vertical prismatic joint carrying 2 of the arms and cameras
        torso_joint="torso_lift_joint",
        # why: one gripper-like end
        arms={
            "arm": ArmDescription(
                name="arm",
                # why: child of arm_7_joint, the last joint before the fingers
                end_effector_link="arm_7_link",
                # why: no frame of the URDF reaches the fingers: added 0.266 m out along the
                #   approach
                tool_frame="arm_standard_tool_frame",
                # why: parent of the first arm joint after the torso; its joints down to the wrist
                #   are found at load
                base_link="torso_lift_link",
                # why: sampled in limits (seed 0): wrist low beside the shoulder, out of view
                # TODO doubt: its links touch (base_link/hand_safety_box,
                #   base_link/hand_thumb_flex_2_link) and no stowed pose was found: give one
                parking={
                    "arm_1_joint": 1.563,
                    "arm_2_joint": -0.881,
                    "arm_3_joint": 0.047,
                    "arm_4_joint": 2.101,
                    "arm_5_joint": -0.116,
                    "arm_6_joint": 1.065,
                    "arm_7_joint": -0.479,
                },
                # why: no <mimic> couples the hand: its 29 curling joints move together; open at the
                #   lower limit, where the fingers part
                # TODO doubt: 7 more hand joint(s) move with no gripper joint: hand_thumb_joint,
                #   hand_index_joint, hand_mrl_joint, hand_index_abd_joint, hand_middle_abd_joint,
                #   hand_ring_abd_joint, ...; couple them (<mimic> or the gripper model) if they are
                #   fingers
                gripper=GripperDescription.curling(),
            ),
        },
        # why: camera frame by name (4 found, best first); optical: z looks forward; others:
        #   xtion_optical_frame, xtion_rgb_frame, xtion_link
        cameras=(
            CameraDescription(
                # why: heights 1.067 to 1.417 m over the base (torso at its limits) are derived at
                #   load; give minimal_height and maximal_height to override
                frame="xtion_rgb_optical_frame",
                # why: the URDF's Gazebo sensor 'xtion_frame_sensor' on xtion_rgb_frame at 640 x 480
                #   pixels
                horizontal_fov=1.0996,
                vertical_fov=0.8616,
            ),
        ),
        # why: two joints turn the camera: the first pans, the second tilts
        pan_tilt=PanTiltDescription(pan_joint="head_1_joint", tilt_joint="head_2_joint"),
        # why: head at zero: straight ahead
        neck_parking={"head_1_joint": 0.0, "head_2_joint": 0.0},
        extra_frames=(
            FrameSpec(
                name="arm_standard_tool_frame",
                parent="arm_7_link",
                pose=Pose((0.0062, 0.007268, 0.266075), (0.707107, 0.0, 0.707107, 0.0)),
            ),
        ),
    )

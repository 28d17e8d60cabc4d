"""baxter: a robot description drafted by `robocram robot draft` from baxter.urdf.

Check it with `robocram robot check baxter.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

import math

from robocram.robots import (
    ArmDescription,
    CameraDescription,
    FrameSpec,
    RobotDescription,
    example_robot_data_folder,
)
from robocram.tf import Pose

URDF = example_robot_data_folder() / "baxter_description/urdf/baxter.urdf"


def description() -> RobotDescription:
    """The baxter description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="baxter",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="base",
        # why: it stands on pedestal, rigid with its root, and has no driven wheels: fixed
        # TODO doubt: say 'holonomic' (or 'differential') if the pedestal rolls on driven wheels
        base_type="fixed",
        # why: two alike arms 1.824 m apart (left: larger y)
        arms={
            "right": ArmDescription(
                name="right",
                # why: child of right_w2, the last joint before the fingers
                end_effector_link="right_wrist",
                # why: right_gripper is at the fingers but its axes differ: turned to x = approach,
                #   y = opening
                tool_frame="right_standard_tool_frame",
                # why: parent of the first arm joint; its joints down to the wrist are found at load
                base_link="right_arm_mount",
                # why: mimicked by 1 hand joint(s) (<mimic> in the URDF); fingers and hand links are
                #   found at load
                gripper_joints=("r_gripper_l_finger_joint",),
                # why: it carries the camera: the wrist 0.25 m ahead of and 0.2 m above the
                #   shoulder, the hand below it, 1 cm clear of its other links (meshes)
                parking={
                    "right_s0": -1.05,
                    "right_s1": -1.316,
                    "right_e0": 1.962,
                    "right_e1": 2.523,
                    "right_w0": -2.704,
                    "right_w1": -0.448,
                    "right_w2": 2.702,
                },
            ),
            "left": ArmDescription(
                name="left",
                # why: child of left_w2, the last joint before the fingers
                end_effector_link="left_wrist",
                # why: left_gripper is at the fingers but its axes differ: turned to x = approach, y
                #   = opening
                tool_frame="left_standard_tool_frame",
                # why: parent of the first arm joint; its joints down to the wrist are found at load
                base_link="left_arm_mount",
                # why: mimicked by 1 hand joint(s) (<mimic> in the URDF); fingers and hand links are
                #   found at load
                gripper_joints=("l_gripper_l_finger_joint",),
                # why: sampled in limits (seed 0): wrist low beside the shoulder, out of view
                # TODO doubt: its links touch (collision_head_link_2/left_upper_elbow_visual,
                #   left_upper_forearm_visual/left_upper_elbow_visual) and no stowed pose was found:
                #   give one
                parking={
                    "left_s0": -1.195,
                    "left_s1": -1.972,
                    "left_e0": 2.214,
                    "left_e1": 2.618,
                    "left_w0": -2.677,
                    "left_w1": -1.157,
                    "left_w2": 2.329,
                },
            ),
        },
        # why: camera frame on the right arm: head_camera_link cannot tilt and sees, at the
        #   shoulder's height, no nearer than 0.85 of the arm's reach; named like a camera on an
        #   arm, which aims it: its own z is its optical axis (x share 0.24, the arms parked);
        #   others: head_camera_link, left_hand_camera_link, left_hand_camera_axis_link
        cameras=(
            CameraDescription(
                # why: heights 0.283 to 0.283 m over the base (torso at its limits) are derived at
                #   load; give minimal_height and maximal_height to override
                frame="right_hand_camera_link",
                # TODO doubt: the URDF gives no field of view: take the sensor's
                horizontal_fov=math.radians(60),
                vertical_fov=math.radians(45),
            ),
        ),
        extra_frames=(
            FrameSpec(
                name="right_standard_tool_frame",
                parent="right_gripper",
                pose=Pose((0.0, 0.0, 0.0), (0.0, -0.707107, 0.0, 0.707107)),
            ),
            FrameSpec(
                name="left_standard_tool_frame",
                parent="left_gripper",
                pose=Pose((0.0, 0.0, 0.0), (0.707107, 0.0, 0.707107, 0.0)),
            ),
        ),
        # why: their collision meshes' convex hulls reach past the meshes (torso's 0.17 m,
        #   pedestal's 0.27 m; over 0.10 m): they collide as their convex parts, not as one hull
        decomposed_links=("torso", "pedestal"),
    )

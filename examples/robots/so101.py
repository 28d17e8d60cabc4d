"""so101_new_calib: a robot description drafted by `robocram robot draft` from so101.urdf.

Check it with `robocram robot check so101.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

from robocram.robots import ArmDescription, FrameSpec, RobotDescription, example_robot_data_folder
from robocram.tf import Pose

URDF = example_robot_data_folder() / "so_arm_description/urdf/so101.urdf"


def description() -> RobotDescription:
    """The so101_new_calib description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="so101_new_calib",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="base_link",
        # why: no driven wheels in the URDF: the default
        # TODO doubt: holonomic assumed; say 'differential' for two wheels on one axle, 'fixed' for
        #   a base that stays
        base_type="holonomic",
        # why: one gripper-like end
        arms={
            "arm": ArmDescription(
                name="arm",
                # why: child of wrist_roll, the last joint before the fingers
                end_effector_link="gripper_link",
                # why: gripper_frame_link is at the fingers but its axes differ: turned to x =
                #   approach, y = opening
                tool_frame="arm_standard_tool_frame",
                # why: parent of the first arm joint; its joints down to the wrist are found at load
                base_link="base_link",
                # why: the finger joints (prismatic, or leaves) right below the wrist; fingers and
                #   hand links are found at load
                gripper_joints=("gripper",),
                # why: sampled in limits (seed 0): wrist low beside the shoulder, out of view
                # TODO doubt: no collision check here: `robocram robot check` drives it
                parking={
                    "shoulder_pan": 0.055,
                    "shoulder_lift": -1.506,
                    "elbow_flex": 0.152,
                    "wrist_flex": 1.089,
                    "wrist_roll": -1.618,
                },
            ),
        },
        # TODO doubt: no camera link found by name: draft again with `--camera LINK` (likely
        #   'gripper_link') to look and detect objects
        cameras=(),
        extra_frames=(
            FrameSpec(
                name="arm_standard_tool_frame",
                parent="gripper_frame_link",
                pose=Pose((0.0, 0.0, 0.0), (-0.500001, 0.499999, -0.499999, -0.500001)),
            ),
        ),
    )

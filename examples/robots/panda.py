"""panda: a robot description drafted by `robocram robot draft` from panda.urdf.

Check it with `robocram robot check panda.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

from robocram.robots import ArmDescription, FrameSpec, RobotDescription, example_robot_data_folder
from robocram.tf import Pose

URDF = example_robot_data_folder() / "panda_description/urdf/panda.urdf"


def description() -> RobotDescription:
    """The panda description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="panda",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="panda_link0",
        # why: no driven wheels in the URDF: the default
        # TODO doubt: holonomic assumed; say 'differential' for two wheels on one axle, 'fixed' for
        #   a base that stays
        base_type="holonomic",
        # why: one gripper-like end
        arms={
            "arm": ArmDescription(
                name="arm",
                # why: child of panda_joint7, the last joint before the fingers
                end_effector_link="panda_link7",
                # why: panda_hand_tcp is at the fingers but its axes differ: turned to x = approach,
                #   y = opening
                tool_frame="arm_standard_tool_frame",
                # why: parent of the first arm joint; its joints down to the wrist are found at load
                base_link="panda_link0",
                # why: mimicked by 1 hand joint(s) (<mimic> in the URDF); fingers and hand links are
                #   found at load
                gripper_joints=("panda_finger_joint1",),
                # why: stowed: within limits, the arm within 0.17 m of the base's middle (the
                #   sampled pose: touching), 1 cm clear of its other links (meshes)
                parking={
                    "panda_joint1": -2.897,
                    "panda_joint2": -0.063,
                    "panda_joint3": 0.73,
                    "panda_joint4": -3.071,
                    "panda_joint5": 2.23,
                    "panda_joint6": 3.752,
                    "panda_joint7": 0.915,
                },
            ),
        },
        # TODO doubt: no camera link found by name: draft again with `--camera LINK` (likely
        #   'panda_link7') to look and detect objects
        cameras=(),
        extra_frames=(
            FrameSpec(
                name="arm_standard_tool_frame",
                parent="panda_hand_tcp",
                pose=Pose((0.0, 0.0, 0.0), (0.0, -0.707107, 0.0, 0.707107)),
            ),
        ),
    )

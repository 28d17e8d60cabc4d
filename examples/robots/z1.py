"""z1_description: a robot description drafted by `robocram robot draft` from z1.urdf.

Check it with `robocram robot check z1.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

from robocram.robots import (
    ArmDescription,
    FrameSpec,
    GripperDescription,
    GripperJoint,
    RobotDescription,
    example_robot_data_folder,
)
from robocram.tf import Pose

URDF = example_robot_data_folder() / "z1_description/urdf/z1.urdf"


def description() -> RobotDescription:
    """The z1_description description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="z1_description",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="world",
        # why: no driven wheels in the URDF: the default
        # TODO doubt: holonomic assumed; say 'differential' for two wheels on one axle, 'fixed' for
        #   a base that stays
        base_type="holonomic",
        # why: one gripper-like end
        arms={
            "arm": ArmDescription(
                name="arm",
                # why: child of joint6, the last joint before the fingers
                end_effector_link="link06",
                # why: no frame of the URDF reaches the fingers: added 0.140 m out along the
                #   approach
                tool_frame="arm_standard_tool_frame",
                # why: parent of the first arm joint; its joints down to the wrist are found at load
                base_link="link00",
                # why: stowed: within limits, the arm within 0.18 m of the base's middle (the
                #   sampled pose: 0.32 m out), 1 cm clear of its other links (meshes)
                parking={
                    "joint1": 1.228,
                    "joint2": 1.799,
                    "joint3": -0.128,
                    "joint4": 0.802,
                    "joint5": -1.304,
                    "joint6": 2.184,
                },
                # why: the finger joints (prismatic, or leaves) right below the wrist; open at the
                #   lower limit, where the fingers part
                gripper=GripperDescription(
                    (GripperJoint("jointGripper", open=-1.5707, closed=0.0),)
                ),
            ),
        },
        # TODO doubt: no camera link found by name: draft again with `--camera LINK` (likely
        #   'link06') to look and detect objects
        cameras=(),
        extra_frames=(
            FrameSpec(
                name="arm_standard_tool_frame",
                parent="link06",
                pose=Pose((0.139501, 0.0, 0.002626), (0.707107, 0.0, 0.0, 0.707107)),
            ),
        ),
    )

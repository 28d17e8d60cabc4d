"""z1_description: a robot description drafted by `robocram robot draft` from z1.urdf.

Check it with `robocram robot check z1.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

import math

from robocram.robots import (
    ArmDescription,
    CameraDescription,
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
        # why: the URDF's root link is 'world': the robot is fixed to it
        # TODO doubt: say 'holonomic' (or 'differential') if the arm rides on a mobile base
        base_type="fixed",
        # why: one gripper-like end
        arms={
            "arm": ArmDescription(
                name="arm",
                # why: child of joint6, the last joint before the fingers
                end_effector_link="link06",
                # why: one jaw turns against a fixed one: added in the middle of the opening between
                #   the fixed jaw's inner face and the moving jaw open, 0.170 m out along the
                #   approach
                tool_frame="arm_standard_tool_frame",
                # why: parent of the first arm joint; its joints down to the wrist are found at load
                base_link="link00",
                # why: it carries the camera: the wrist 0.25 m ahead of and 0.2 m above the
                #   shoulder, the hand below it, 1 cm clear of its other links (meshes)
                parking={
                    "joint1": 0.2,
                    "joint2": 1.894,
                    "joint3": -1.082,
                    "joint4": 1.518,
                    "joint5": -1.343,
                    "joint6": -1.06,
                },
                # why: the finger joints (prismatic, or leaves) right below the wrist; open at the
                #   lower limit, where the fingers part
                gripper=GripperDescription(
                    (GripperJoint("jointGripper", open=-1.5707, closed=0.0),)
                ),
            ),
        },
        # why: camera frame inferred: no link is named like a camera; the link off the arms named
        #   like a head or sensor, else the highest, else a wrist; neither its z (x share -0.26) nor
        #   its x (0.04) looks ahead, the arms parked: optical frame added looking ahead (the base's
        #   x), 12 deg down
        # TODO doubt: inferred, not read from the URDF: the camera is put on 'link06'; if the
        #   robot's camera sits elsewhere, draft again with `robocram robot draft URDF --camera
        #   LINK`, or edit this frame
        cameras=(
            CameraDescription(
                # why: heights 0.161 to 0.161 m over the base (torso at its limits) are derived at
                #   load; give minimal_height and maximal_height to override
                frame="link06_optical",
                # TODO doubt: the URDF gives no field of view: take the sensor's
                horizontal_fov=math.radians(60),
                vertical_fov=math.radians(45),
            ),
        ),
        extra_frames=(
            FrameSpec(
                name="arm_standard_tool_frame",
                parent="link06",
                pose=Pose((0.169751, 0.0, 0.015251), (0.707107, 0.0, 0.0, 0.707107)),
            ),
            FrameSpec(
                name="link06_optical",
                parent="link06",
                pose=Pose((0.0, 0.0, 0.0), (0.721476, 0.081014, -0.024924, 0.687232)),
            ),
        ),
    )

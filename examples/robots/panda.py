"""panda: a robot description drafted by `robocram robot draft` from panda.urdf.

Check it with `robocram robot check panda.py`; look at each `TODO doubt`.
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

URDF = example_robot_data_folder() / "panda_description/urdf/panda.urdf"


def description() -> RobotDescription:
    """The panda description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="panda",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="panda_link0",
        # why: one chain of 7 joints ending in a hand of 2 fingers, on a 0.23 m mount, no wheels,
        #   legs, head or second arm: a lone arm
        # TODO doubt: say 'holonomic' (or 'differential') if the arm rides on a mobile base
        base_type="fixed",
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
                # why: it carries the camera: the wrist 0.25 m ahead of and 0.2 m above the
                #   shoulder, the hand below it, 1 cm clear of its other links (meshes)
                parking={
                    "panda_joint1": -2.498,
                    "panda_joint2": 0.997,
                    "panda_joint3": 2.838,
                    "panda_joint4": -2.847,
                    "panda_joint5": 1.173,
                    "panda_joint6": 2.514,
                    "panda_joint7": 0.236,
                },
            ),
        },
        # why: camera frame inferred: no link is named like a camera; the link off the arms named
        #   like a head or sensor, else the highest, else a wrist; its x looks forward (body
        #   convention), the arms parked: optical frame added
        # TODO doubt: inferred, not read from the URDF: the camera is put on 'panda_link7'; if the
        #   robot's camera sits elsewhere, draft again with `robocram robot draft URDF --camera
        #   LINK`, or edit this frame
        cameras=(
            CameraDescription(
                # why: heights 1.033 to 1.033 m over the base (torso at its limits) are derived at
                #   load; give minimal_height and maximal_height to override
                frame="panda_link7_optical",
                # TODO doubt: the URDF gives no field of view: take the sensor's
                horizontal_fov=math.radians(60),
                vertical_fov=math.radians(45),
            ),
        ),
        extra_frames=(
            FrameSpec(
                name="arm_standard_tool_frame",
                parent="panda_hand_tcp",
                pose=Pose((0.0, 0.0, 0.0), (0.0, -0.707107, 0.0, 0.707107)),
            ),
            FrameSpec(
                name="panda_link7_optical",
                parent="panda_link7",
                pose=Pose((0.0, 0.0, 0.0), (-0.5, 0.5, -0.5, 0.5)),
            ),
        ),
    )

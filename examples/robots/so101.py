"""so101_new_calib: a robot description drafted by `robocram robot draft` from so101.urdf.

Check it with `robocram robot check so101.py`; look at each `TODO doubt`.
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

URDF = example_robot_data_folder() / "so_arm_description/urdf/so101.urdf"


def description() -> RobotDescription:
    """The so101_new_calib description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="so101_new_calib",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="base_link",
        # why: one chain of 6 joints on a 0.11 m mount, no wheels: a lone arm
        # TODO doubt: say 'holonomic' (or 'differential') if the arm rides on a mobile base
        base_type="fixed",
        # why: one gripper-like end
        arms={
            "arm": ArmDescription(
                name="arm",
                # why: child of wrist_roll, the last joint before the fingers
                end_effector_link="gripper_link",
                # why: one jaw turns against a fixed one: added in the middle of the opening between
                #   the fixed jaw's inner face and the moving jaw open, 0.080 m out along the
                #   approach
                tool_frame="arm_standard_tool_frame",
                # why: parent of the first arm joint; its joints down to the wrist are found at load
                base_link="base_link",
                # why: the finger joints (prismatic, or leaves) right below the wrist; fingers and
                #   hand links are found at load
                gripper_joints=("gripper",),
                # why: it carries the camera: the wrist 0.25 m ahead of and 0.2 m above the
                #   shoulder, the hand below it, 1 cm clear of its other links (meshes)
                parking={
                    "shoulder_pan": -0.006,
                    "shoulder_lift": 0.203,
                    "elbow_flex": -0.674,
                    "wrist_flex": 0.924,
                    "wrist_roll": 1.316,
                },
            ),
        },
        # why: camera frame inferred: no link is named like a camera; the link off the arms named
        #   like a head or sensor, else the highest, else a wrist; neither its z (x share -0.90) nor
        #   its x (0.13) looks ahead, the arms parked: optical frame added looking ahead (the base's
        #   x), 13 deg down
        # TODO doubt: inferred, not read from the URDF: the camera is put on 'gripper_link'; if the
        #   robot's camera sits elsewhere, draft again with `robocram robot draft URDF --camera
        #   LINK`, or edit this frame
        cameras=(
            CameraDescription(
                # why: heights 0.234 to 0.234 m over the base (torso at its limits) are derived at
                #   load; give minimal_height and maximal_height to override
                frame="gripper_link_optical",
                # TODO doubt: the URDF gives no field of view: take the sensor's
                horizontal_fov=math.radians(60),
                vertical_fov=math.radians(45),
            ),
        ),
        extra_frames=(
            FrameSpec(
                name="arm_standard_tool_frame",
                parent="gripper_link",
                pose=Pose((0.024335, -0.0001, -0.080306), (-0.5, -0.5, 0.5, -0.5)),
            ),
            FrameSpec(
                name="gripper_link_optical",
                parent="gripper_link",
                pose=Pose((0.0, 0.0, 0.0), (-0.149142, 0.981878, -0.115978, 0.014864)),
            ),
        ),
    )

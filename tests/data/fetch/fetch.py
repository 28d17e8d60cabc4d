"""fetch: a robot description drafted by `robocram robot draft` from fetch.urdf.

Check it with `robocram robot check fetch.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

import math
from pathlib import Path

from robocram.robots import ArmDescription, CameraDescription, PanTiltDescription, RobotDescription

URDF = Path(__file__).resolve().parent / "fetch_description/robots/fetch.urdf"


def description() -> RobotDescription:
    """The fetch description (unchecked; load_description checks it)."""
    return RobotDescription(
        name="fetch",
        urdf=URDF,
        # why: the URDF's root link: the robot's base
        base_frame="base_link",
        # why: r_wheel_joint and l_wheel_joint drive two wheels on one axle: no sideways motion
        base_type="differential",
        # why: vertical prismatic joint carrying 2 of the arms and cameras
        torso_joint="torso_lift_joint",
        # why: one gripper-like end
        arms={
            "arm": ArmDescription(
                name="arm",
                # why: child of wrist_roll_joint, the last joint before the fingers
                end_effector_link="wrist_roll_link",
                # why: the URDF's frame at the fingers, x = approach
                tool_frame="gripper_link",
                # why: parent of the first arm joint after the torso; its joints down to the wrist
                #   are found at load
                base_link="torso_lift_link",
                # why: the finger joints (prismatic, or leaves) right below the wrist; fingers and
                #   hand links are found at load
                gripper_joints=("r_gripper_finger_joint", "l_gripper_finger_joint"),
                # why: stowed: within limits, the arm within 0.40 m of the base's middle (the
                #   sampled pose: touching), 1 cm clear of its other links (meshes)
                parking={
                    "shoulder_pan_joint": 0.105,
                    "shoulder_lift_joint": 1.198,
                    "upperarm_roll_joint": 1.458,
                    "elbow_flex_joint": -2.155,
                    "forearm_roll_joint": -2.039,
                    "wrist_flex_joint": 1.604,
                    "wrist_roll_joint": 0.162,
                },
            ),
        },
        # why: camera frame by name (3 found, best first); optical: z looks forward; others:
        #   head_camera_rgb_frame, head_camera_link
        cameras=(
            CameraDescription(
                # why: heights 1.061 to 1.447 m over the base (torso at its limits) are derived at
                #   load; give minimal_height and maximal_height to override
                frame="head_camera_rgb_optical_frame",
                # TODO doubt: the URDF gives no field of view: take the sensor's
                horizontal_fov=math.radians(60),
                vertical_fov=math.radians(45),
            ),
        ),
        # why: two joints turn the camera: the first pans, the second tilts
        pan_tilt=PanTiltDescription(pan_joint="head_pan_joint", tilt_joint="head_tilt_joint"),
        # why: head at zero: straight ahead
        neck_parking={"head_pan_joint": 0.0, "head_tilt_joint": 0.0},
    )

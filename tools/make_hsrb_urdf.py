"""Write src/robocram/robots/data/hsrb.urdf: our own Toyota HSR-B model of simple shapes.

Kinematics (joint names, types, origins, axes, limits, mimic tags) are the HSR-B's published
facts; every shape and mass is our own estimate. Run ``python tools/make_hsrb_urdf.py``.
"""

from __future__ import annotations

import math
from pathlib import Path

from urdf_shapes import Limit, MimicTag, UrdfBuilder, box, cylinder, sphere

HALF_PI = math.pi / 2
OPTICAL_RPY = (-HALF_PI, 0.0, -HALF_PI)  # body (x forward) -> optical (z forward, x right)
OUT = Path(__file__).resolve().parents[1] / "src/robocram/robots/data/hsrb.urdf"
COMMENT = """
  robocram's own model of the Toyota HSR-B, written by tools/make_hsrb_urdf.py (do not edit).
  Real kinematics: joint names, types, origins, axes, limits and mimic relations of the HSR-B,
  including torso_lift_joint = 0.5 * arm_lift_joint. Every link is a few boxes, cylinders or
  spheres sized like the real part; masses are estimates, inertias those of solid primitives.
  Left out (sensor-only or simulator-only, no CRAM predicate needs them): the *_gazebo_frame
  links, the passive caster x/y frames (each caster is one sphere on a fixed joint), the
  laser and IMU plugins. Base wheels and base_roll_joint are fixed: the world moves the base.
  hand_tool_frame is not in this file: the robocram description adds it in code.
"""


def base(b: UrdfBuilder) -> None:
    """Base with its fixed wheels, the lower column and base sensors."""
    b.link("base_footprint")
    b.joint("base_footprint_joint", "fixed", "base_footprint", "base_link")
    body = cylinder(0.2, 0.28, (0.0, 0.0, 0.19))
    column = box(0.16, 0.18, 0.42, (-0.02, 0.0, 0.54))
    b.link("base_link", (body, column), mass=50.0, color="white")
    b.joint("base_roll_joint", "fixed", "base_link", "base_roll_link")
    b.link("base_roll_link", (cylinder(0.17, 0.02, (0.0, 0.0, 0.06)),), mass=10.0, color="dark")
    for side, y in (("r", -0.133), ("l", 0.133)):
        wheel = cylinder(0.04, 0.03, rpy=(HALF_PI, 0.0, 0.0))
        b.joint(
            f"base_{side}_drive_wheel_joint",
            "fixed",
            "base_roll_link",
            f"base_{side}_drive_wheel_link",
            (-0.11, y, 0.04),
        )
        b.link(f"base_{side}_drive_wheel_link", (wheel,), mass=0.2, color="dark")
    for side, y in (("r", -0.055), ("l", 0.055)):
        b.joint(
            f"base_{side}_passive_wheel_z_joint",
            "fixed",
            "base_roll_link",
            f"base_{side}_passive_wheel_z_link",
            (0.1495, y, 0.03),
        )
        b.link(f"base_{side}_passive_wheel_z_link", (sphere(0.03),), mass=0.2, color="dark")
    b.joint(
        "base_range_sensor_joint",
        "fixed",
        "base_link",
        "base_range_sensor_link",
        (0.1675, 0, 0.1844),
    )
    b.link("base_range_sensor_link", (cylinder(0.03, 0.05),), mass=0.16, color="dark")
    b.frame(
        "base_imu_frame",
        "base_link",
        "base_imu_frame_joint",
        (0.0005, 0.1296, 0.181),
        (math.pi, 0, 0),
    )


def torso_and_head(b: UrdfBuilder) -> None:
    """Telescopic torso (mimics half the arm lift), pan-tilt head and its cameras."""
    b.joint(
        "torso_lift_joint",
        "prismatic",
        "base_link",
        "torso_lift_link",
        (0.0, 0.0, 0.752),
        axis=(0.0, 0.0, 1.0),
        limit=Limit(0.0, 0.345, 0.1, 100.0),
        mimic=MimicTag("arm_lift_joint", 0.5, 0.0),
    )
    b.link(
        "torso_lift_link", (box(0.12, 0.15, 0.40, (-0.04, 0.0, -0.21)),), mass=3.42, color="white"
    )
    b.joint(
        "head_pan_joint",
        "revolute",
        "torso_lift_link",
        "head_pan_link",
        axis=(0.0, 0.0, 1.0),
        limit=Limit(-3.84, 1.75, 1.0, 100.0),
    )
    b.link("head_pan_link", (cylinder(0.05, 0.05, (0.0, 0.0, -0.025)),), mass=0.57, color="dark")
    b.joint(
        "head_tilt_joint",
        "revolute",
        "head_pan_link",
        "head_tilt_link",
        (0.02, 0.0, 0.0),
        axis=(0.0, -1.0, 0.0),
        limit=Limit(-1.57, 0.52, 1.0, 100.0),
    )
    head = box(0.12, 0.2, 0.14, (-0.07, 0.0, 0.08))
    b.link("head_tilt_link", (head,), mass=2.12, color="white")
    cameras = (
        ("head_l_stereo_camera_link", "head_l_stereo_camera_joint", (0.02, 0.07, 0.061)),
        ("head_r_stereo_camera_link", "head_r_stereo_camera_joint", (0.02, -0.07, 0.061)),
        ("head_center_camera_frame", "head_center_camera_frame_joint", (0.0195, 0.0, 0.061)),
    )
    for link, joint, xyz in cameras:
        b.frame(link, "head_tilt_link", joint, xyz, OPTICAL_RPY)
    b.joint(
        "head_rgbd_sensor_joint",
        "fixed",
        "head_tilt_link",
        "head_rgbd_sensor_link",
        (-0.079796, 0.022, 0.215172),
        OPTICAL_RPY,
    )
    sensor = box(0.18, 0.035, 0.04, (-0.022, 0.0, -0.025))  # in the optical frame: x right
    b.link("head_rgbd_sensor_link", (sensor,), mass=0.25, color="dark")


def arm(b: UrdfBuilder) -> None:
    """Arm lift, flex, roll and the two wrist joints."""
    b.joint(
        "arm_lift_joint",
        "prismatic",
        "base_link",
        "arm_lift_link",
        (0.0, 0.0, 0.34),
        axis=(0.0, 0.0, 1.0),
        limit=Limit(0.0, 0.69, 0.2, 100.0),
    )
    shoulder = box(0.2, 0.12, 0.12, (0.07, 0.04, -0.05))
    b.link("arm_lift_link", (shoulder,), mass=1.28, color="white")
    b.joint(
        "arm_flex_joint",
        "revolute",
        "arm_lift_link",
        "arm_flex_link",
        (0.141, 0.078, 0.0),
        axis=(0.0, -1.0, 0.0),
        limit=Limit(-2.62, 0.0, 1.2, 100.0),
    )
    b.link("arm_flex_link", (cylinder(0.045, 0.25, (0.0, 0.0, 0.125)),), mass=1.34, color="white")
    b.joint(
        "arm_roll_joint",
        "revolute",
        "arm_flex_link",
        "arm_roll_link",
        (0.005, 0.0, 0.345),
        axis=(0.0, 0.0, 1.0),
        limit=Limit(-2.09, 3.84, 2.0, 100.0),
    )
    b.link("arm_roll_link", (cylinder(0.04, 0.08, (0.0, 0.0, -0.05)),), mass=0.25, color="white")
    b.joint(
        "wrist_flex_joint",
        "revolute",
        "arm_roll_link",
        "wrist_flex_link",
        axis=(0.0, -1.0, 0.0),
        limit=Limit(-1.92, 1.22, 1.5, 100.0),
    )
    b.link("wrist_flex_link", (cylinder(0.017, 0.04, (0.0, 0.0, 0.03)),), mass=0.68, color="dark")
    b.joint(
        "wrist_roll_joint",
        "revolute",
        "wrist_flex_link",
        "wrist_roll_link",
        axis=(0.0, 0.0, 1.0),
        limit=Limit(-1.92, 3.67, 1.5, 100.0),
    )
    b.link("wrist_roll_link", (cylinder(0.04, 0.08, (0.0, 0.0, 0.09)),), mass=0.76, color="white")
    b.frame(
        "wrist_ft_sensor_frame",
        "wrist_roll_link",
        "wrist_ft_sensor_frame_joint",
        (0, 0, 0.0735),
        (math.pi, 0, 0),
    )
    b.frame(
        "gripper_tool_frame",
        "wrist_roll_link",
        "gripper_tool_joint",
        (0, 0, 0.2309),
        (0, 0, HALF_PI),
    )


def hand(b: UrdfBuilder) -> None:
    """Palm, motor and the two fingers with their mimic and spring joints."""
    b.joint(
        "hand_palm_joint",
        "fixed",
        "wrist_roll_link",
        "hand_palm_link",
        (0.012, 0, 0.1405),
        (0, 0, math.pi),
    )
    b.link("hand_palm_link", (box(0.07, 0.1, 0.035, (0.0, 0.0, -0.0175)),), mass=0.15, color="dark")
    grip = Limit(-0.798, 1.24, 1.0, 100.0)
    b.joint(
        "hand_motor_joint",
        "revolute",
        "hand_palm_link",
        "hand_motor_dummy_link",
        axis=(1, 0, 0),
        limit=grip,
    )
    b.link("hand_motor_dummy_link")
    b.frame("hand_camera_frame", "hand_palm_link", "hand_camera_frame_joint", (0.039, 0.0, -0.0045))
    for side, sign in (("l", 1.0), ("r", -1.0)):
        finger(b, side, sign)


def finger(b: UrdfBuilder, side: str, sign: float) -> None:
    """One finger: proximal (mimics the motor), spring, mimic distal and distal joints."""
    axis = (sign, 0.0, 0.0)
    p = f"hand_{side}_"
    b.joint(
        f"{p}proximal_joint",
        "revolute",
        "hand_palm_link",
        f"{p}proximal_link",
        (-0.01675, -sign * 0.0245, -0.0175),
        axis=axis,
        limit=Limit(-0.798, 1.24, 1.0, 100.0),
        mimic=MimicTag("hand_motor_joint"),
    )
    b.link(f"{p}proximal_link")
    b.joint(
        f"{p}spring_proximal_joint",
        "revolute",
        f"{p}proximal_link",
        f"{p}spring_proximal_link",
        axis=axis,
        limit=Limit(0.0, 0.698, 1.0, 100.0),
    )
    blade = box(0.02, 0.012, 0.07, (0.01675, 0.0, 0.035))
    b.link(f"{p}spring_proximal_link", (blade,), mass=0.044, color="grey")
    b.joint(
        f"{p}mimic_distal_joint",
        "revolute",
        f"{p}spring_proximal_link",
        f"{p}mimic_distal_link",
        (0.0, 0.0, 0.07),
        axis=axis,
        limit=Limit(-0.698, 0.0, 1.0, 100.0),
        mimic=MimicTag(f"{p}spring_proximal_joint", -1.0),
    )
    b.link(f"{p}mimic_distal_link")
    b.joint(
        f"{p}distal_joint",
        "revolute",
        f"{p}mimic_distal_link",
        f"{p}distal_link",
        axis=axis,
        limit=Limit(-1.24, 0.798, 1.0, 100.0),
        mimic=MimicTag("hand_motor_joint", -1.0, -0.087),
    )
    tip = box(0.02, 0.012, 0.045, (0.01675, sign * 0.004, 0.0225))
    b.link(f"{p}distal_link", (tip,), mass=0.028, color="grey")
    b.frame(
        f"{p}finger_tip_frame",
        f"{p}distal_link",
        f"{p}finger_tip_frame_joint",
        (0.01675, sign * 0.0193, 0.0379),
        (-sign * HALF_PI, 0.0, 0.0),
    )
    if side == "l":
        b.frame(
            "hand_l_finger_vacuum_frame",
            "hand_l_distal_link",
            "hand_l_finger_vacuum_frame_joint",
            (0.00475, -0.011539, 0.03322),
            (math.pi / 4, 0.0, 0.0),
        )


def main() -> None:
    """Build the model and write it next to the package's other URDFs."""
    b = UrdfBuilder("hsrb", COMMENT)
    for part in (base, torso_and_head, arm, hand):
        part(b)
    OUT.write_text(b.xml(), encoding="utf-8")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()

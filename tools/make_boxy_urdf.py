"""Write src/robocram/robots/data/boxy.urdf: our own model of IAI's Boxy of simple shapes.

Kinematics (joint names, types, origins, axes, limits, mimic tags) are Boxy's published,
calibrated facts; every shape and mass is our own estimate. Run ``python tools/make_boxy_urdf.py``.
"""

from __future__ import annotations

import math
from pathlib import Path

from urdf_shapes import Limit, MimicTag, Shape, UrdfBuilder, Vec3, box, cylinder, sphere

PI = math.pi
OUT = Path(__file__).resolve().parents[1] / "src/robocram/robots/data/boxy.urdf"
ALONG_X = (0.0, PI / 2, 0.0)  # turns a cylinder's z axis onto x
COMMENT = """
  robocram's own model of IAI's Boxy, written by tools/make_boxy_urdf.py (do not edit).
  Real kinematics: joint names, types, origins, axes, limits and mimic relations of Boxy's
  calibrated description (triangle_base_joint torso, two KUKA LWR4+ arms with WSG-50 grippers,
  a UR3 neck carrying a Kinect2). Every link is a few boxes, cylinders or spheres sized like
  the real part; masses are estimates, inertias those of solid primitives.
  Changed or left out: the root is base_footprint (the odom_x/odom_y/odom_z joints are gone:
  the world moves the base); the laser reference frames and the two planning "limit boxes"
  are left out; each arm's six fixed adapter frames between the flange and the gripper
  (cabling adaptor, ISO50/KMS40 plates, KMS40 force sensor, FWK/FWA tool changer) are
  folded into one fixed joint of their summed offset, left_/right_gripper_anterior_gripper_joint.
"""
KUKA_LIMITS: tuple[tuple[Vec3, float, float, float], ...] = (
    # axis, |limit| [rad], velocity [rad/s], effort [N m]; origin of joint i is z 0.11 then 0.2...
    ((0, 0, 1), 2.61799387799, 1.91986217719, 204.0),
    ((0, -1, 0), 1.86750229963, 1.91986217719, 306.0),
    ((0, 0, 1), 2.61799387799, 2.26892802759, 204.0),
    ((0, 1, 0), 1.86750229963, 2.26892802759, 306.0),
    ((0, 0, 1), 2.61799387799, 2.26892802759, 204.0),
    ((0, -1, 0), 2.00712863979, PI, 306.0),
    ((0, 0, 1), 2.61799387799, PI, 204.0),
)
KUKA_OFFSETS = (0.11, 0.2, 0.2, 0.2, 0.2, 0.19, 0.0)  # [m] along z of the parent link
ADAPTER_STACK = 0.01 + 0.016 + 0.027 + 0.01 + 0.0141 + 0.01  # [m] flange -> gripper base


def base_and_torso(b: UrdfBuilder) -> None:
    """Omni base, torso column and the prismatic triangle that carries both arms."""
    b.link("base_footprint")
    b.joint("base_footprint_joint", "fixed", "base_footprint", "base_link", (0.36, 0.25, 0.16))
    b.link(
        "base_link", (box(0.885, 0.557, 0.57, (-0.252, -0.228, 0.125)),), mass=70.0, color="grey"
    )
    b.joint("torso_joint", "fixed", "base_link", "torso_base_link", (0.0, 0.065, 0.41))
    column = box(0.12, 0.5, 1.08, (0.0, -0.285, 0.54))
    b.link("torso_base_link", (column,), mass=3.83, color="white")
    b.joint(
        "triangle_base_joint",
        "prismatic",
        "base_link",
        "triangle_base_link",
        (0.0786889663592487, 0.0986351579738104, 0.996332096493862),
        axis=(0.0, 0.0, 1.0),
        limit=Limit(-0.586, 0.0, 0.02, 0.0),
    )
    carriage = box(0.14, 0.36, 0.14, (0.05, -0.30, 0.09))
    b.link("triangle_base_link", (carriage,), mass=7.37, color="blue")
    b.frame(
        "triangle_left_arm_link",
        "triangle_base_link",
        "triangle_left_arm_joint",
        (0.134209, -0.240707, 0.181709),
        (1.046186267441739, 0.005429697608281147, 3.1340705895651766),
    )
    b.frame(
        "triangle_right_arm_link",
        "triangle_base_link",
        "triangle_right_arm_joint",
        (0.133262, -0.366684, 0.181581),
        (1.0482088349514576, -0.00542969760828114, -0.0075220640246236),
    )


def kuka_arm(b: UrdfBuilder, side: str, mount_xyz: Vec3, mount_rpy: Vec3) -> None:
    """One KUKA LWR4+ from its calibrated base link to the flange."""
    base = f"calib_{side}_arm_base_link"
    b.joint(
        f"triangle_{side}_arm_link_{side}_arm_base_joint",
        "fixed",
        f"triangle_{side}_arm_link",
        base,
        mount_xyz,
        mount_rpy,
    )
    b.link(base, (cylinder(0.07, 0.11, (0.0, 0.0, 0.055)),), mass=2.0, color="orange")
    parent = base
    for i, ((axis, limit, velocity, effort), offset) in enumerate(
        zip(KUKA_LIMITS, KUKA_OFFSETS, strict=True)
    ):
        child = f"{side}_arm_{i + 1}_link"
        b.joint(
            f"{side}_arm_{i}_joint",
            "revolute",
            parent,
            child,
            (0.0, 0.0, offset),
            axis=axis,
            limit=Limit(-limit, limit, velocity, effort),
        )
        b.link(child, (_kuka_shape(i + 1),), mass=2.0, color="orange")
        parent = child
    b.joint(f"{side}_arm_flange_joint", "fixed", parent, f"{side}_arm_flange_link", (0, 0, 0.078))
    stack = cylinder(0.04, ADAPTER_STACK, (0.0, 0.0, ADAPTER_STACK / 2))
    b.link(f"{side}_arm_flange_link", (stack,), mass=0.5, color="dark")


def _kuka_shape(index: int) -> Shape:
    """Shape of LWR link ``index``: a segment up to the next joint, the wrist ball, the hand."""
    if index <= 4:
        return cylinder(0.06, 0.2, (0.0, 0.0, 0.1))
    if index == 5:
        return cylinder(0.06, 0.19, (0.0, 0.0, 0.095))
    if index == 6:
        return sphere(0.06)
    return cylinder(0.04, 0.078, (0.0, 0.0, 0.039))


def wsg50(b: UrdfBuilder, side: str) -> None:
    """A Weiss WSG-50 gripper: the opening width is the master, one finger mimics -1/2 of it."""
    g = f"{side}_gripper"
    b.joint(
        f"{g}_anterior_gripper_joint",
        "fixed",
        f"{side}_arm_flange_link",
        f"{g}_base_link",
        (0.0, 0.0, ADAPTER_STACK),
    )
    b.link(
        f"{g}_base_link", (box(0.146, 0.052, 0.055, (0.0, 0.0, 0.0275)),), mass=1.2, color="dark"
    )
    b.joint(
        f"{g}_base_gripper_left_joint",
        "prismatic",
        f"{g}_base_link",
        f"{g}_gripper_left_link",
        axis=(1.0, 0.0, 0.0),
        limit=Limit(-0.055, -0.0027, 0.42, 1.0),
        mimic=MimicTag(f"{g}_joint", -0.5),
    )
    guide = box(0.02, 0.03, 0.02, (-0.01, 0.0, 0.01))
    finger = box(0.014, 0.02, 0.08, (-0.007, 0.0, 0.075))
    b.link(f"{g}_gripper_left_link", (guide,), mass=0.1, color="grey")
    b.joint(
        f"{g}_guide_joint_finger_left",
        "fixed",
        f"{g}_gripper_left_link",
        f"{g}_finger_left_link",
        (0.0, 0.0, 0.023),
    )
    b.link(f"{g}_finger_left_link", (finger,), mass=0.1, color="white")
    b.joint(
        f"{g}_joint",
        "prismatic",
        f"{g}_gripper_left_link",
        f"{g}_gripper_right_link",
        rpy=(0.0, 0.0, 3.14159),
        axis=(-1.0, 0.0, 0.0),
        limit=Limit(0.0065, 0.109, 0.42, 1.0),
    )
    b.link(f"{g}_gripper_right_link", (guide,), mass=0.1, color="grey")
    b.joint(
        f"{g}_guide_joint_finger_right",
        "fixed",
        f"{g}_gripper_right_link",
        f"{g}_finger_right_link",
        (0.0, 0.0, 0.023),
    )
    b.link(f"{g}_finger_right_link", (finger,), mass=0.1, color="white")
    b.frame(f"{g}_tool_frame", f"{g}_base_link", f"{g}_tool_frame_joint", (0.0, 0.0, 0.144))


def left_wrist_camera(b: UrdfBuilder) -> None:
    """The optical frame of the camera on the left wrist (a frame only)."""
    b.frame(
        "left_wrist_optical_frame_x",
        "left_gripper_base_link",
        "left_wrist_optical_joint_x",
        (0.000836, -0.053028, 0.073603),
        (0.007552, 6.274592, 3.141201),
    )
    b.frame(
        "left_wrist_optical_frame",
        "left_wrist_optical_frame_x",
        "left_wrist_optical_joint",
        rpy=(0.0, 0.0, 3.141519),
    )


def ur3_neck(b: UrdfBuilder) -> None:
    """The UR3 neck on top of the torso column, with its calibrated joint origins."""
    b.joint(
        "neck_adapter_ur3_in_joint",
        "fixed",
        "base_link",
        "neck_adapter_ur3_frame_in",
        (0.175, -0.227, 1.48),
    )
    b.link("neck_adapter_ur3_frame_in", (box(0.1, 0.18, 0.006),), mass=0.2, color="dark")
    b.frame(
        "neck_adapter_ur3_frame_out",
        "neck_adapter_ur3_frame_in",
        "neck_adapter_ur3_trans_frame_out",
        (0.0, 0.0, 0.003),
    )
    b.joint(
        "neck_base_mounting_joint",
        "fixed",
        "neck_adapter_ur3_frame_out",
        "neck_base_link",
        rpy=(0.0, 0.0, -PI / 2),
    )
    b.link("neck_base_link", (cylinder(0.064, 0.08, (0.0, 0.0, 0.04)),), mass=2.0, color="grey")
    b.frame("neck_base", "neck_base_link", "neck_base_link-base_fixed_joint", rpy=(0, 0, -PI))
    parent = "neck_base_link"
    for name, child, xyz, rpy, effort, velocity, shape, mass in NECK_JOINTS:
        b.joint(
            name,
            "revolute",
            parent,
            child,
            xyz,
            rpy,
            axis=(0.0, 0.0, 1.0),
            limit=Limit(-PI, PI, velocity, effort),
        )
        b.link(child, (shape,), mass=mass, color="grey")
        parent = child
    b.frame("neck_ee_link", "neck_wrist_3_link", "neck_ee_fixed_joint", rpy=(0.0, -PI / 2, PI / 2))
    b.frame("neck_tool0", "neck_wrist_3_link", "neck_wrist_3_passive_joint")
    kinect2(b)


NECK_JOINTS = (
    # joint, child link, origin xyz, origin rpy, effort [N m], velocity [rad/s], shape, mass [kg]
    (
        "neck_shoulder_pan_joint",
        "neck_shoulder_link",
        (0.0, 0.0, 0.152535796718),
        (0.0, 0.0, 3.14155032165),
        330.0,
        2.16,
        cylinder(0.05, 0.12),
        2.0,
    ),
    (
        "neck_shoulder_lift_joint",
        "neck_upper_arm_link",
        (-0.000156529268713, 0.0, 0.0),
        (1.57107408073, 0.0, -0.000172993120302),
        330.0,
        2.16,
        cylinder(0.045, 0.244, (-0.122, 0.0, 0.0), ALONG_X),
        3.42,
    ),
    (
        "neck_elbow_joint",
        "neck_forearm_link",
        (-0.243779809951, 0.0, 0.0),
        (0.0062325747024, -0.00321790421944, -0.000142376414564),
        150.0,
        3.15,
        cylinder(0.035, 0.214, (-0.107, 0.0, 0.03), ALONG_X),
        1.26,
    ),
    (
        "neck_wrist_1_joint",
        "neck_wrist_1_link",
        (-0.214100722965, 0.000727675582482, 0.112244141512),
        (3.1351097728, -3.1392629132, 3.14154211848),
        54.0,
        3.2,
        cylinder(0.032, 0.09, (0.0, 0.0, -0.045)),
        0.8,
    ),
    (
        "neck_wrist_2_joint",
        "neck_wrist_2_link",
        (-5.48666558441e-05, -0.0854004865941, -0.000115923346558),
        (1.57215373446, 0.0, -3.85172795334e-05),
        54.0,
        3.2,
        cylinder(0.032, 0.085, (0.0, 0.0, -0.04)),
        0.8,
    ),
    (
        "neck_wrist_3_joint",
        "neck_wrist_3_link",
        (0.000108171881403, 0.0824484877801, -7.5350917985e-06),
        (1.57070493529, PI, -3.14157463707),
        54.0,
        3.2,
        cylinder(0.032, 0.03, (0.0, 0.0, -0.015)),
        0.35,
    ),
)


def kinect2(b: UrdfBuilder) -> None:
    """The ISO50 adapter and the Kinect2, whose RGB optical frame is the camera frame."""
    b.joint(
        "neck_adapter_iso50_kinect2_joint",
        "fixed",
        "neck_tool0",
        "neck_adapter_iso50_kinect2_frame_in",
        rpy=(0.0, 0.0, -1.570795),
    )
    plate = cylinder(0.032, 0.02, (0.0, 0.0, 0.01))
    b.link("neck_adapter_iso50_kinect2_frame_in", (plate,), mass=0.1, color="dark")
    b.frame(
        "neck_adapter_iso50_kinect2_frame_out",
        "neck_adapter_iso50_kinect2_frame_in",
        "neck_adapter_iso50_kinect2_trans_frame_out",
        (0.0, 0.0, 0.02),
    )
    b.joint(
        "head_mount_kinect2_in_joint",
        "fixed",
        "neck_adapter_iso50_kinect2_frame_out",
        "head_mount_kinect2_rgb_optical_frame",
        (-0.031284, 0.098627, 0.023544),
        (4.728550, 6.279385, 1.578295),
    )
    body = box(0.25, 0.066, 0.07, KINECT_BODY_IN_OPTICAL)
    b.link("head_mount_kinect2_rgb_optical_frame", (body,), mass=1.0, color="dark")


KINECT_BODY_IN_OPTICAL: Vec3 = (-0.05, 0.0, -0.036)  # [m]: the RGB lens sits off-centre, in front


def main() -> None:
    """Build the model and write it next to the package's other URDFs."""
    b = UrdfBuilder("boxy", COMMENT)
    base_and_torso(b)
    kuka_arm(b, "left", (-0.006185, 0.004080, -0.010726), (6.276354, 6.281653, 1.074679))
    kuka_arm(b, "right", (0.0, 0.0, 0.0), (0.0, 0.0, -1.047198))
    for side in ("left", "right"):
        wsg50(b, side)
    left_wrist_camera(b)
    ur3_neck(b)
    OUT.write_text(b.xml(), encoding="utf-8")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()

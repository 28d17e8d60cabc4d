"""Our own Boxy model: real calibrated kinematics, two arms and a neck arm with the Kinect2,
loads in PyBullet and pinocchio. Expected numbers are facts of Boxy's published description."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin
import pybullet as p
import pytest

from robocram.robots import RobotDescription, load_description, mimic_followers

if TYPE_CHECKING:
    from conftest import Sim

TOL = 1e-6
MIDDLE_Y = 0.045  # [m] over base_footprint: halfway between the two arm mounts


@pytest.fixture(scope="module")
def boxy() -> RobotDescription:
    return load_description("boxy")


@pytest.fixture(scope="module")
def robot(boxy: RobotDescription) -> RobotDescription:
    return boxy


@pytest.fixture(scope="module")
def sim(robot_in_pybullet: Sim) -> Sim:
    return robot_in_pybullet


def test_two_arms_and_a_neck_arm_with_the_camera(boxy: RobotDescription) -> None:
    assert sorted(boxy.arms) == ["left", "neck", "right"]
    assert boxy.neck_arm == "neck" and boxy.pan_tilt is None
    assert boxy.arms["neck"].tool_frame == boxy.cameras[0].frame
    assert boxy.cameras[0].frame == "head_mount_kinect2_rgb_optical_frame"
    for side in ("left", "right"):
        arm = boxy.arms[side]
        assert arm.joints == tuple(f"{side}_arm_{i}_joint" for i in range(7))
        assert arm.tool_frame == f"{side}_standard_gripper_tool_frame"
        assert arm.gripper_joints == (f"{side}_gripper_joint",)
    assert len(boxy.arms["neck"].joints) == 6
    assert boxy.torso_joint == "triangle_base_joint" and boxy.base_frame == "base_footprint"


@pytest.mark.parametrize(
    ("joint", "kind", "lower", "upper", "axis", "xyz"),
    [
        ("triangle_base_joint", "prismatic", -0.586, 0.0, (0, 0, 1), (0.07869, 0.09864, 0.99633)),
        ("left_arm_0_joint", "revolute", -2.61799, 2.61799, (0, 0, 1), (0.0, 0.0, 0.11)),
        ("left_arm_1_joint", "revolute", -1.86750, 1.86750, (0, -1, 0), (0.0, 0.0, 0.2)),
        ("right_arm_3_joint", "revolute", -1.86750, 1.86750, (0, 1, 0), (0.0, 0.0, 0.2)),
        ("right_arm_5_joint", "revolute", -2.00713, 2.00713, (0, -1, 0), (0.0, 0.0, 0.19)),
        ("left_gripper_joint", "prismatic", 0.0065, 0.109, (-1, 0, 0), (0.0, 0.0, 0.0)),
        ("neck_elbow_joint", "revolute", -math.pi, math.pi, (0, 0, 1), (-0.24378, 0.0, 0.0)),
        ("neck_shoulder_pan_joint", "revolute", -math.pi, math.pi, (0, 0, 1), (0, 0, 0.15254)),
    ],
)
def test_joint_facts(
    boxy: RobotDescription,
    joint: str,
    kind: str,
    lower: float,
    upper: float,
    axis: tuple[float, float, float],
    xyz: tuple[float, float, float],
) -> None:
    assert boxy.model is not None
    j = boxy.model.joints[joint]
    assert j.type == kind
    assert j.lower == pytest.approx(lower, abs=1e-5)
    assert j.upper == pytest.approx(upper, abs=1e-5)
    assert j.axis == pytest.approx(axis, abs=TOL)
    assert j.origin.position == pytest.approx(xyz, abs=1e-5)


def test_gripper_fingers_open_by_the_master_width(sim: Sim, boxy: RobotDescription) -> None:
    assert boxy.model is not None
    values = mimic_followers(boxy.model, {"left_gripper_joint": 0.08})
    assert values["left_gripper_base_gripper_left_joint"] == pytest.approx(-0.04, abs=TOL)
    sim.set(values)
    base, rotation = sim.frame("left_gripper_base_link")
    fingers = [sim.frame(f"left_gripper_finger_{s}_link")[0] - base for s in ("left", "right")]
    across = [float(f @ rotation[:, 0]) for f in fingers]  # fingers slide along gripper x
    assert across == pytest.approx([-0.04, 0.04], abs=1e-4)


def test_left_and_right_tool_frames_mirror_in_y(sim: Sim) -> None:
    sim.set({})
    left, _ = sim.frame("left_gripper_tool_frame")
    right, _ = sim.frame("right_gripper_tool_frame")
    assert left[1] - MIDDLE_Y == pytest.approx(MIDDLE_Y - right[1], abs=0.04)
    assert left[2] == pytest.approx(right[2], abs=0.01)
    assert left[0] == pytest.approx(right[0], abs=0.04)  # the calibrated mounts differ slightly
    mounts = [sim.frame(f"triangle_{s}_arm_link")[0] for s in ("left", "right")]
    assert (mounts[0][1] + mounts[1][1]) / 2 == pytest.approx(MIDDLE_Y, abs=0.005)


def test_parking_holds_the_grippers_down_beside_the_base(sim: Sim, boxy: RobotDescription) -> None:
    parking = {**boxy.arms["left"].parking, **boxy.arms["right"].parking}
    sim.set(parking)
    for side, y in (("left", 0.45), ("right", -0.36)):
        tool, _ = sim.frame(f"{side}_gripper_tool_frame")
        assert tool == pytest.approx((0.6, y, 0.9), abs=2e-3)


def test_neck_parking_looks_ahead_and_down(sim: Sim, boxy: RobotDescription) -> None:
    sim.set(boxy.neck_parking)
    position, rotation = sim.frame(boxy.cameras[0].frame)
    assert position == pytest.approx((0.62, 0.04, 1.75), abs=2e-3)
    down = math.radians(40.0)
    assert rotation[:, 2] == pytest.approx((math.cos(down), 0.0, -math.sin(down)), abs=5e-3)
    assert rotation[:, 0] == pytest.approx((0.0, -1.0, 0.0), abs=5e-3)  # image x: robot's right
    camera = boxy.cameras[0]
    assert camera.minimal_height < position[2] < camera.maximal_height
    assert camera.horizontal_fov == pytest.approx(1.468, abs=0.01)


def test_lowering_the_torso_lowers_both_arms(sim: Sim) -> None:
    heights = []
    for torso in (0.0, -0.586):
        sim.set({"triangle_base_joint": torso})
        heights.append([sim.frame(f"{s}_gripper_tool_frame")[0][2] for s in ("left", "right")])
    assert np.subtract(heights[0], heights[1]) == pytest.approx([0.586, 0.586], abs=1e-6)


def _reach(model: pin.Model, frame: str, joints: list[str], target: np.ndarray) -> float:
    """Distance [m] left after damped least-squares position IK from the zero pose."""
    data = model.createData()
    q = pin.neutral(model)
    fid = model.getFrameId(frame)
    ids = [model.getJointId(j) for j in joints]
    for _ in range(200):
        pin.framesForwardKinematics(model, data, q)
        error = target - data.oMf[fid].translation
        if np.linalg.norm(error) < 1e-5:
            break
        jac = pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL_WORLD_ALIGNED)[:3]
        jac = jac[:, [model.joints[i].idx_v for i in ids]]
        step = jac.T @ np.linalg.solve(jac @ jac.T + 1e-3 * np.eye(3), error)
        for i, dq in zip(ids, step, strict=True):
            k = model.joints[i].idx_q
            q[k] = np.clip(q[k] + dq, model.lowerPositionLimit[k], model.upperPositionLimit[k])
    return float(np.linalg.norm(error))


@pytest.mark.parametrize(("side", "y"), [("left", 0.25), ("right", -0.16)])
def test_grippers_reach_a_table_in_front(boxy: RobotDescription, side: str, y: float) -> None:
    model = pin.buildModelFromUrdf(str(boxy.urdf))
    joints = ["triangle_base_joint", *boxy.arms[side].joints]
    target = np.array([0.95, y, 0.85])  # 5 cm over a table top at 0.8 m, 0.95 m ahead
    assert _reach(model, f"{side}_gripper_tool_frame", joints, target) < 1e-3


def test_pybullet_and_pinocchio_agree(sim: Sim, boxy: RobotDescription) -> None:
    assert boxy.model is not None
    model = pin.buildModelFromUrdf(str(boxy.urdf))
    data = model.createData()
    values = {"triangle_base_joint": -0.3, "left_arm_1_joint": 0.7, "neck_elbow_joint": 1.2}
    values.update({"right_arm_3_joint": -1.0, "right_gripper_joint": 0.05})
    q = pin.neutral(model)
    full = mimic_followers(boxy.model, values)
    for name, value in full.items():
        q[model.joints[model.getJointId(name)].idx_q] = value
    pin.framesForwardKinematics(model, data, q)
    sim.set(full)
    frames = ("left_gripper_tool_frame", "right_gripper_finger_right_link", boxy.cameras[0].frame)
    for link in frames:
        assert sim.frame(link)[0] == pytest.approx(
            data.oMf[model.getFrameId(link)].translation, abs=1e-6
        )
    masses = [
        p.getDynamicsInfo(sim.body, i, physicsClientId=sim.client)[0] for i in sim.links.values()
    ]
    assert min(masses) > 0.0
    assert set(sim.links) | {"base_footprint"} == set(boxy.model.links)


@pytest.mark.parametrize("side", ["left", "right"])
def test_standard_tool_frame_has_x_approach_and_y_opening(sim: Sim, side: str) -> None:
    _, boxy_tool = sim.frame(f"{side}_gripper_tool_frame")
    _, standard = sim.frame(f"{side}_standard_gripper_tool_frame")
    assert np.allclose(standard[:, 0], boxy_tool[:, 2], atol=1e-6)  # approach
    assert np.allclose(standard[:, 1], boxy_tool[:, 0], atol=1e-6)  # opening

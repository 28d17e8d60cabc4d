"""Our own HSR-B model: real kinematics, one arm, the added tool frame, loads in PyBullet and
pinocchio. Expected numbers are facts of the published HSR-B description."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin
import pybullet as p
import pytest

from robocram.robots import (
    DescriptionCheckError,
    RobotDescription,
    load_description,
    mimic_followers,
)
from robocram.robots.builtin.hsrb import description

if TYPE_CHECKING:
    from conftest import Sim

TOL = 1e-6


@pytest.fixture(scope="module")
def hsrb() -> RobotDescription:
    return load_description("hsrb")


@pytest.fixture(scope="module")
def robot(hsrb: RobotDescription) -> RobotDescription:
    return hsrb


@pytest.fixture(scope="module")
def sim(robot_in_pybullet: Sim) -> Sim:
    return robot_in_pybullet


def test_hsr_alias_and_the_single_arm(hsrb: RobotDescription) -> None:
    alias = load_description("hsr")
    assert alias.name == hsrb.name == "hsrb"
    assert list(hsrb.arms) == ["arm"]
    arm = hsrb.arms["arm"]
    assert arm.joints == (
        "arm_flex_joint",
        "arm_roll_joint",
        "wrist_flex_joint",
        "wrist_roll_joint",
    )
    assert arm.links[-1] == "hand_palm_link"
    assert arm.gripper_joints == ("hand_motor_joint",)
    assert hsrb.torso_joint == "arm_lift_joint"
    assert hsrb.base_frame == "base_footprint"


@pytest.mark.parametrize(
    ("joint", "kind", "lower", "upper", "axis", "xyz"),
    [
        ("arm_lift_joint", "prismatic", 0.0, 0.69, (0, 0, 1), (0.0, 0.0, 0.34)),
        ("torso_lift_joint", "prismatic", 0.0, 0.345, (0, 0, 1), (0.0, 0.0, 0.752)),
        ("arm_flex_joint", "revolute", -2.62, 0.0, (0, -1, 0), (0.141, 0.078, 0.0)),
        ("arm_roll_joint", "revolute", -2.09, 3.84, (0, 0, 1), (0.005, 0.0, 0.345)),
        ("wrist_flex_joint", "revolute", -1.92, 1.22, (0, -1, 0), (0.0, 0.0, 0.0)),
        ("wrist_roll_joint", "revolute", -1.92, 3.67, (0, 0, 1), (0.0, 0.0, 0.0)),
        ("head_pan_joint", "revolute", -3.84, 1.75, (0, 0, 1), (0.0, 0.0, 0.0)),
        ("head_tilt_joint", "revolute", -1.57, 0.52, (0, -1, 0), (0.02, 0.0, 0.0)),
        ("hand_motor_joint", "revolute", -0.798, 1.24, (1, 0, 0), (0.0, 0.0, 0.0)),
        (
            "hand_r_proximal_joint",
            "revolute",
            -0.798,
            1.24,
            (-1, 0, 0),
            (-0.01675, 0.0245, -0.0175),
        ),
    ],
)
def test_joint_facts(
    hsrb: RobotDescription,
    joint: str,
    kind: str,
    lower: float,
    upper: float,
    axis: tuple[float, float, float],
    xyz: tuple[float, float, float],
) -> None:
    assert hsrb.model is not None
    j = hsrb.model.joints[joint]
    assert j.type == kind
    assert j.lower == pytest.approx(lower, abs=TOL)
    assert j.upper == pytest.approx(upper, abs=TOL)
    assert j.axis == pytest.approx(axis, abs=TOL)
    assert j.origin.position == pytest.approx(xyz, abs=TOL)


def test_mimic_relations_of_torso_and_fingers(hsrb: RobotDescription) -> None:
    assert hsrb.model is not None
    values = mimic_followers(hsrb.model, {"arm_lift_joint": 0.6, "hand_motor_joint": 0.9})
    assert values["torso_lift_joint"] == pytest.approx(0.3, abs=TOL)
    assert values["hand_l_proximal_joint"] == pytest.approx(0.9, abs=TOL)
    assert values["hand_r_proximal_joint"] == pytest.approx(0.9, abs=TOL)
    assert values["hand_l_distal_joint"] == pytest.approx(-0.9 - 0.087, abs=TOL)
    assert values["hand_r_distal_joint"] == pytest.approx(-0.9 - 0.087, abs=TOL)
    spring = mimic_followers(hsrb.model, {"hand_l_spring_proximal_joint": 0.5})
    assert spring["hand_l_mimic_distal_joint"] == pytest.approx(-0.5, abs=TOL)


def test_tool_frame_is_added_in_code_in_front_of_the_palm(hsrb: RobotDescription) -> None:
    assert hsrb.model is not None
    joint = hsrb.model.parent_joint("hand_tool_frame")
    assert joint is not None and joint.parent == "hand_palm_link" and joint.type == "fixed"
    assert joint.origin.position == pytest.approx((0.0, 0.0, 0.08), abs=TOL)
    assert 'name="hand_tool_frame"' not in Path(str(description().urdf)).read_text(encoding="utf-8")


def test_pybullet_loads_every_link_with_positive_mass(sim: Sim, hsrb: RobotDescription) -> None:
    assert hsrb.model is not None
    assert set(sim.links) | {"base_footprint"} == set(hsrb.model.links)
    masses = [
        p.getDynamicsInfo(sim.body, i, physicsClientId=sim.client)[0] for i in sim.links.values()
    ]
    assert min(masses) > 0.0
    # 50 kg base (as heavy as the reference makes it, for a steady base) + 10 kg wheel unit
    assert sum(masses) == pytest.approx(72.0, abs=0.5)  # the added tool frame weighs 1 g


def test_camera_heights_follow_half_the_arm_lift(sim: Sim, hsrb: RobotDescription) -> None:
    assert hsrb.model is not None
    camera = hsrb.cameras[0]
    heights = []
    for lift in (0.0, 0.69):
        sim.set(mimic_followers(hsrb.model, {"arm_lift_joint": lift}))
        position, rotation = sim.frame(camera.frame)
        heights.append(position[2])
        assert rotation[:, 2] == pytest.approx((1.0, 0.0, 0.0), abs=1e-6)  # z looks ahead
        assert rotation[:, 0] == pytest.approx((0.0, -1.0, 0.0), abs=1e-6)  # x to the right
    assert heights[1] - heights[0] == pytest.approx(0.5 * 0.69, abs=1e-6)
    assert heights[0] == pytest.approx(camera.minimal_height, abs=1e-6)
    assert heights[1] == pytest.approx(camera.maximal_height, abs=1e-6)
    assert camera.horizontal_fov == pytest.approx(1.01, abs=0.02)
    assert camera.vertical_fov == pytest.approx(0.785, abs=0.02)


def test_arm_lift_raises_the_hand_by_its_full_travel(sim: Sim, hsrb: RobotDescription) -> None:
    assert hsrb.model is not None
    tools = []
    for lift in (0.0, 0.69):
        sim.set(mimic_followers(hsrb.model, {"arm_lift_joint": lift}))
        tools.append(sim.frame("hand_tool_frame")[0])
    low, high = tools
    assert high - low == pytest.approx((0.0, 0.0, 0.69), abs=1e-6)


def test_tool_frame_sits_between_the_finger_tips(sim: Sim, hsrb: RobotDescription) -> None:
    assert hsrb.model is not None
    sim.set(mimic_followers(hsrb.model, {"arm_lift_joint": 0.0, "hand_motor_joint": 0.0}))
    tool, tool_rotation = sim.frame("hand_tool_frame")
    palm, palm_rotation = sim.frame("hand_palm_link")
    tips = [sim.frame(f"hand_{s}_finger_tip_frame")[0] for s in ("l", "r")]
    middle = (tips[0] + tips[1]) / 2
    assert np.linalg.norm(tool - middle) < 0.03
    assert tool_rotation[:, 0] == pytest.approx(palm_rotation[:, 2], abs=1e-6)  # x: approach
    opening = (tips[0] - tips[1]) / np.linalg.norm(tips[0] - tips[1])
    assert abs(float(opening @ tool_rotation[:, 1])) > 0.99  # fingers open along tool y
    assert float((tool - palm) @ palm_rotation[:, 2]) == pytest.approx(0.08, abs=1e-6)


def test_parking_tucks_the_hand_over_the_base(sim: Sim, hsrb: RobotDescription) -> None:
    assert hsrb.model is not None
    arm = hsrb.arms["arm"]
    assert arm.parking == {
        "arm_flex_joint": 0.0,
        "arm_roll_joint": -1.57,
        "wrist_flex_joint": -1.57,
        "wrist_roll_joint": 0.0,
    }
    sim.set(mimic_followers(hsrb.model, {"arm_lift_joint": 0.0, **arm.parking}))
    tool, _ = sim.frame("hand_tool_frame")
    assert math.hypot(tool[0], tool[1]) < 0.25  # inside the base's 0.2 m radius + hand
    assert tool[2] == pytest.approx(0.685, abs=0.02)  # wrist height with the lift down


def test_pinocchio_builds_the_same_kinematics(sim: Sim, hsrb: RobotDescription) -> None:
    urdf = Path(str(hsrb.urdf))
    model = pin.buildModelFromUrdf(str(urdf))
    assert model.nq == 17
    data = model.createData()
    q = pin.neutral(model)
    for name, value in {
        "arm_lift_joint": 0.3,
        "torso_lift_joint": 0.15,
        "arm_flex_joint": -1.0,
    }.items():
        q[model.joints[model.getJointId(name)].idx_q] = value
    pin.framesForwardKinematics(model, data, q)
    assert hsrb.model is not None
    sim.set(mimic_followers(hsrb.model, {"arm_lift_joint": 0.3, "arm_flex_joint": -1.0}))
    for link in ("hand_palm_link", "head_rgbd_sensor_link", "gripper_tool_frame"):
        expected = data.oMf[model.getFrameId(link)].translation
        assert sim.frame(link)[0] == pytest.approx(expected, abs=1e-6)


def test_misnamed_torso_joint_names_the_fix() -> None:
    wrong = replace(description(), torso_joint="arm_lift")
    with pytest.raises(DescriptionCheckError, match="arm_lift_joint"):
        load_description(wrong)

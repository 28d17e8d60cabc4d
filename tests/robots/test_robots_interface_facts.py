"""Interface facts of a description: the values plans read through the robot predicates."""

from __future__ import annotations

import math
from collections import defaultdict
from typing import Any

import pytest

from robocram.logic import KnowledgeBase
from robocram.logic.terms import NIL, Term
from robocram.robots import RobotDescription, install_description, load_description
from robocram.robots.interface_facts import (
    INTERFACE_PREDICATES,
    description_facts,
)

RIGHT_JOINTS = [
    "r_shoulder_pan_joint",
    "r_shoulder_lift_joint",
    "r_upper_arm_roll_joint",
    "r_elbow_flex_joint",
    "r_forearm_roll_joint",
    "r_wrist_flex_joint",
    "r_wrist_roll_joint",
]


def _python(value: Any) -> Any:
    """A Prolog list cell chain as a Python list (recursively); other values as they are."""
    if value == NIL:
        return []
    if isinstance(value, Term) and value.name == "." and value.arity == 2:
        return [_python(value.args[0]), *_python(value.args[1])]
    return value


def _index(desc: RobotDescription) -> dict[str, list[tuple[Any, ...]]]:
    facts: dict[str, list[tuple[Any, ...]]] = defaultdict(list)
    for fact in description_facts(desc):
        facts[f"{fact.name}/{fact.arity}"].append(tuple(_python(a) for a in fact.args))
    return facts


@pytest.fixture(scope="module")
def pr2_facts() -> dict[str, list[tuple[Any, ...]]]:
    return _index(load_description("pr2"))


def test_every_fact_is_a_declared_interface_predicate(pr2_facts: dict[str, Any]) -> None:
    assert set(pr2_facts) <= set(INTERFACE_PREDICATES)


def test_pr2_robot_and_arm_facts(pr2_facts: dict[str, list[tuple[Any, ...]]]) -> None:
    assert pr2_facts["robot/1"] == [("pr2",)]
    assert pr2_facts["robot_base_frame/2"] == [("pr2", "base_footprint")]
    assert pr2_facts["robot_odom_frame/2"] == [("pr2", "odom_combined")]
    assert pr2_facts["robot_torso_link_joint/3"] == [("pr2", "torso_lift_link", "torso_lift_joint")]
    assert sorted(pr2_facts["arm/2"]) == [("pr2", "left"), ("pr2", "right")]
    assert ("pr2", "right", RIGHT_JOINTS) in pr2_facts["arm_joints/3"]
    assert ("pr2", "right", "r_gripper_tool_frame") in pr2_facts["robot_tool_frame/3"]
    assert ("pr2", "left", "l_wrist_roll_link") in pr2_facts["end_effector_link/3"]
    assert ("pr2", "right", "r_gripper_l_finger_joint") in pr2_facts["gripper_joint/3"]
    parking = dict(pr2_facts["robot_arms_parking_joint_states/3"][1][2])
    assert parking["r_elbow_flex_joint"] == pytest.approx(-2.12)


def test_pr2_head_and_camera_facts(pr2_facts: dict[str, list[tuple[Any, ...]]]) -> None:
    assert pr2_facts["robot_pan_tilt_links/3"] == [("pr2", "head_pan_link", "head_tilt_link")]
    assert pr2_facts["robot_pan_tilt_joints/3"] == [("pr2", "head_pan_joint", "head_tilt_joint")]
    assert pr2_facts["camera_frame/2"] == [("pr2", "wide_stereo_optical_frame")]
    assert pr2_facts["camera_minimal_height/2"][0][1] == pytest.approx(1.27)
    assert pr2_facts["camera_maximal_height/2"][0][1] == pytest.approx(1.58)


def test_pr2_urdf_facts(pr2_facts: dict[str, list[tuple[Any, ...]]]) -> None:
    upper = {j: v for _, j, v in pr2_facts["joint_upper_limit/3"]}
    lower = {j: v for _, j, v in pr2_facts["joint_lower_limit/3"]}
    assert upper["torso_lift_joint"] == pytest.approx(0.31)
    assert lower["r_elbow_flex_joint"] == pytest.approx(-2.3213)
    assert (lower["r_wrist_roll_joint"], upper["r_wrist_roll_joint"]) == (-math.inf, math.inf)
    assert "r_gripper_palm_joint" not in upper  # fixed joints have no limits
    types = {j: t for _, j, t in pr2_facts["joint_type/3"]}
    assert (
        types["torso_lift_joint"] == "prismatic" and types["r_forearm_roll_joint"] == "continuous"
    )
    axes = {j: a for _, j, a in pr2_facts["joint_axis/3"]}
    assert axes["torso_lift_joint"] == [0.0, 0.0, 1.0]
    parents = {j: p for _, j, p in pr2_facts["joint_parent/3"]}
    assert parents["r_shoulder_pan_joint"] == "torso_lift_link"
    mimics = {f[1]: f[2:] for f in pr2_facts["joint_mimic/5"]}
    assert mimics["r_gripper_r_parallel_root_joint"] == ("r_gripper_l_finger_joint", -1.0, 0.0)


def test_quadrotor_facts_have_no_arms() -> None:
    facts = _index(load_description("quadrotor"))
    assert facts["flying_robot/1"] == [("quadrotor",)]
    assert "arm/2" not in facts and "joint_type/3" not in facts


def test_install_puts_several_robots_in_one_knowledge_base() -> None:
    kb = KnowledgeBase()
    for name in ("pr2", "hsrb", "quadrotor"):
        assert install_description(kb, name).model is not None
    assert sorted(a["R"] for a in kb.query("robot(R)")) == ["hsrb", "pr2", "quadrotor"]
    assert kb.first("arm_joints(hsrb, arm, J)") == {
        "J": ["arm_flex_joint", "arm_roll_joint", "wrist_flex_joint", "wrist_roll_joint"]
    }
    assert kb.holds("flying_robot(quadrotor)") and not kb.holds("arm(quadrotor, A)")
    upper = kb.first("joint_upper_limit(pr2, torso_lift_joint, U)")
    assert upper is not None and upper["U"] == pytest.approx(0.31, abs=1e-6)
    install_description(kb, "pr2")  # reloading replaces the group, no duplicates
    assert len(list(kb.query("robot(pr2)"))) == 1

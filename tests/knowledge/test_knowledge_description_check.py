"""A description missing a required predicate is reported with the table's meaning."""

from __future__ import annotations

import pytest

from robocram.knowledge import MissingFact, MissingFactsError, check_facts, missing_in_kb
from robocram.logic import KnowledgeBase
from robocram.robots import load_description
from robocram.robots.interface_facts import description_facts


def test_the_builtin_robots_state_every_required_predicate() -> None:
    for robot in ("pr2", "hsrb", "boxy", "quadrotor"):
        check_facts(description_facts(load_description(robot)))


def test_a_missing_tool_frame_is_named_with_its_meaning() -> None:
    facts = [
        f
        for f in description_facts(load_description("pr2"))
        if not (f.name == "robot_tool_frame" and f.args[1] == "left")
    ]
    with pytest.raises(MissingFactsError) as caught:
        check_facts(facts)
    assert caught.value.missing == (
        MissingFact("pr2", "left", "robot_tool_frame/3", "the frame arm motions put at the target"),
    )
    assert "robot 'pr2' arm 'left' has no robot_tool_frame/3: the frame arm motions" in str(
        caught.value
    )


def test_a_robot_written_in_prolog_is_checked_in_its_knowledge_base() -> None:
    kb = KnowledgeBase()
    kb.consult(
        "robot(arty). robot_base_frame(arty, base_link). arm(arty, main).\n"
        "arm_joints(arty, main, [j1, j2]). robot_tool_frame(arty, main, tool).\n"
    )
    missing = missing_in_kb(kb, "arty")
    assert [(m.arm, m.indicator) for m in missing] == [
        (None, "robot_description/2"),
        (None, "robot_odom_frame/2"),
        ("main", "arm_links/3"),
        ("main", "hand_links/3"),
        ("main", "end_effector_link/3"),
        ("main", "robot_arms_parking_joint_states/3"),
        ("main", "robot_arms_carrying_joint_states/3"),
    ]

"""Typed queries: a predicate of the table answers with its frozen row dataclass."""

from __future__ import annotations

import dataclasses

import pytest

from robocram.knowledge import UnknownArgumentError
from robocram.knowledge.robot_predicates import (
    ARM,
    ROBOT_ARMS_PARKING_JOINT_STATES,
    ROBOT_TOOL_FRAME,
    Arm,
    ArmFrame,
    ParkingPose,
)
from robocram.knowledge.world_predicates import LINK_POSE, LinkPose
from robocram.logic import KnowledgeBase
from robocram.robots import install_description
from robocram.tf import Pose
from robocram.world import World


@pytest.fixture(scope="module")
def pr2_kb() -> KnowledgeBase:
    kb = KnowledgeBase()
    install_description(kb, "pr2")
    return kb


def test_a_row_comes_back_frozen_and_typed(pr2_kb: KnowledgeBase) -> None:
    row = ROBOT_TOOL_FRAME.first(pr2_kb, robot="pr2", arm="left")
    assert row == ArmFrame("pr2", "left", "l_gripper_tool_frame")
    with pytest.raises(dataclasses.FrozenInstanceError):
        row.frame = "elsewhere"  # type: ignore[misc, union-attr]


def test_unbound_arguments_enumerate_in_the_kb_order(pr2_kb: KnowledgeBase) -> None:
    assert list(ARM.answers(pr2_kb, robot="pr2")) == [Arm("pr2", "left"), Arm("pr2", "right")]


def test_joint_states_become_pairs_of_name_and_float(pr2_kb: KnowledgeBase) -> None:
    row = ROBOT_ARMS_PARKING_JOINT_STATES.first(pr2_kb, robot="pr2", arm="right")
    assert isinstance(row, ParkingPose)
    assert len(row.joint_states) == 7
    assert all(isinstance(j, str) and isinstance(v, float) for j, v in row.joint_states)
    assert dict(row.joint_states)["r_elbow_flex_joint"] == -2.12


def test_an_unknown_argument_is_named_with_the_valid_ones(pr2_kb: KnowledgeBase) -> None:
    with pytest.raises(UnknownArgumentError, match="robot_tool_frame/3 has no argument 'hand'"):
        ROBOT_TOOL_FRAME.first(pr2_kb, robot="pr2", hand="left")


def test_a_world_predicate_binds_the_world_itself() -> None:
    with World() as world:
        world.add_box("crate", (0.2, 0.2, 0.2), pose=Pose((1.0, 2.0, 0.1)))
        row = LINK_POSE.first(world.kb, object="crate", link="link0")
        assert isinstance(row, LinkPose)
        assert row.world is world
        assert row.pose.position == pytest.approx((1.0, 2.0, 0.1))

"""The world's predicates in its knowledge base answer with the world's values."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.tf import Pose
from robocram.world import World


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        pr2 = w.add_robot("pr2")
        w.set_joint_states(pr2, {"torso_lift_joint": 0.3, "head_tilt_joint": 0.4})
        w.add_box("table", (0.7, 1.5, 1.0), Pose((1.6, 0, 0.5)))
        w.add_item("pot", "pot", Pose((1.6, 0, 1.075)))
        w.add_item("hidden", "cup", Pose((2.2, 0, 0.045)))
        yield w


@pytest.fixture
def kb(world: World):  # noqa: ANN201  (the logic layer's KnowledgeBase)
    with world.snapshots.stored_state():
        yield world.kb


def test_objects_types_and_poses(world: World, kb) -> None:
    assert kb.first("world(W)") == {"W": world}
    names = [a["O"] for a in kb.query("world(W), object(W, O)")]
    assert names == ["floor", "pr2", "table", "pot", "hidden"]
    assert kb.first("world(W), object_type(W, pot, T)")["T"] == "pot"
    assert [a["R"] for a in kb.query("world(W), robot(W, R)")] == ["pr2"]
    assert [a["A"] for a in kb.query("arm(pr2, A)")] == ["left", "right"]  # its description
    pose = kb.first("world(W), object_pose(W, table, P)")["P"]
    assert pose.position == pytest.approx((1.6, 0, 0.5))
    assert not kb.holds("world(W), object(W, fridge)")


def test_joint_states_are_read_and_set_with_clamping(world: World, kb) -> None:
    answer = kb.first("world(W), joint_state(W, pr2, torso_lift_joint, V)")
    assert answer["V"] == pytest.approx(0.3)
    assert kb.holds("world(W), set_joint_state(W, pr2, torso_lift_joint, 5.0)")
    assert world.joint_states("pr2")["torso_lift_joint"] == pytest.approx(0.31)
    assert len(list(kb.query("world(W), joint_state(W, pr2, J, V)"))) == 30


def test_attachment_predicates(world: World, kb) -> None:
    assert kb.holds("world(W), attach(W, pot, pr2, r_gripper_tool_frame)")
    answer = kb.first("world(W), attached(W, pr2, L, O)")
    assert answer["L"] == "r_gripper_tool_frame" and answer["O"] == "pot"
    assert kb.holds("world(W), detach(W, pot), \\+ attached(W, pr2, Link, pot)")


def test_reasoning_predicates(world: World, kb) -> None:
    assert kb.holds("world(W), contact(W, pot, table)")
    assert kb.holds("world(W), supported_by(W, pot, table)")
    assert [a["S"] for a in kb.query("world(W), supported_by(W, pot, S)")] == ["table"]
    assert kb.holds("world(W), above(W, pot, table), below(W, table, pot)")
    assert kb.holds("world(W), stable(W, pot)")
    assert kb.holds("world(W), visible(W, pr2, pot)")
    assert not kb.holds("world(W), visible(W, pr2, hidden)")
    answer = kb.first("world(W), occluding_objects(W, pr2, hidden, L)")
    assert answer["L"] == ["table"]


def test_simulate_and_set_pose(world: World, kb) -> None:
    assert kb.holds("world(W), set_object_pose(W, pot, [[1.6, 0.0, 1.4], [0, 0, 0, 1]])")
    assert world.pose("pot").position[2] == pytest.approx(1.4)
    assert kb.holds("world(W), simulate(W, 1.0)")
    assert world.pose("pot").position[2] == pytest.approx(1.075, abs=0.01)

"""stored_state restores exactly (objects added or removed included); copies are independent."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.tf import Pose
from robocram.world import UnknownObjectError, World


@pytest.fixture
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        w.add_box("table", (0.8, 0.8, 0.7), Pose((1, 0, 0.35)))
        w.add_item("bottle", "bottle", Pose((1, 0.1, 0.9)))
        w.add_item("mug", "mug", Pose((1, -0.2, 0.7)))
        yield w


def _snapshot(world: World) -> dict[str, Pose]:
    return {o.name: world.pose(o) for o in world.objects()}


def _assert_same(a: dict[str, Pose], b: dict[str, Pose]) -> None:
    assert a.keys() == b.keys()
    for name in a:
        assert a[name].distance_to(b[name]) < 1e-6, name
        assert a[name].angle_to(b[name]) < 1e-6, name


def test_stored_state_restores_poses_and_the_set_of_objects(world: World) -> None:
    world.physics.simulate(0.2)  # the bottle is falling: velocities matter too
    before = _snapshot(world)
    bottle = world.object("bottle")
    with world.snapshots.stored_state():
        world.add_item("plate", "plate", Pose((1, 0.2, 0.8)))
        world.remove("mug")
        world.set_pose("table", Pose((3, 3, 0.35)))
        world.physics.simulate(0.5)
    _assert_same(before, _snapshot(world))
    assert [o.name for o in world.objects()] == ["floor", "table", "bottle", "mug"]
    assert world.object("bottle") is bottle  # handles survive
    with pytest.raises(UnknownObjectError, match="did you mean 'plate'|known"):
        world.object("plate")
    world.physics.simulate(0.3)
    assert world.pose("mug").position[2] == pytest.approx(0.7, abs=0.01)


def test_restore_replays_the_same_fall(world: World) -> None:
    with world.snapshots.stored_state():
        world.physics.simulate(0.3)
        first = world.pose("bottle")
    world.physics.simulate(0.3)
    assert world.pose("bottle").distance_to(first) < 1e-3


def test_removed_object_comes_back_with_its_handle_and_body(world: World) -> None:
    mug = world.object("mug")
    place = world.pose(mug)
    with world.snapshots.stored_state():
        world.remove(mug)
        assert "mug" not in world
    assert world.object("mug") is mug
    assert world.pose(mug).distance_to(place) < 1e-6
    assert world.view.ray_cast((1, -0.2, 2.0), (1, -0.2, 0.0)).obj is mug


def test_copy_is_an_independent_world(world: World) -> None:
    world.physics.simulate(0.1)
    before = _snapshot(world)
    with world.copy() as other:
        assert other.physics.client() != world.physics.client()
        _assert_same(before, _snapshot(other))
        assert other.object("mug") is not world.object("mug")
        other.set_pose("mug", Pose((5, 5, 0.05)))
        other.remove("bottle")
        other.physics.simulate(0.5)
        assert "bottle" in world
    _assert_same(before, _snapshot(world))


def test_copy_keeps_robot_joints_and_attachments(world: World) -> None:
    pr2 = world.add_robot("pr2", Pose((0, 0, 0)))
    world.set_joint_states(pr2, {"torso_lift_joint": 0.25, "r_elbow_flex_joint": -1.0})
    world.set_pose("bottle", world.link_pose(pr2, "r_gripper_tool_frame"))
    world.attach("bottle", pr2, "r_gripper_tool_frame")
    with world.copy() as other:
        assert other.joint_states("pr2") == pytest.approx(world.joint_states(pr2), abs=1e-9)
        assert other.bodies.attachments("pr2") == {"bottle": "r_gripper_tool_frame"}
        other.set_joint_states("pr2", {"torso_lift_joint": 0.0})
        tool = other.link_pose("pr2", "r_gripper_tool_frame")
        assert other.pose("bottle").distance_to(tool) < 1e-6
    assert world.joint_states(pr2)["torso_lift_joint"] == pytest.approx(0.25)

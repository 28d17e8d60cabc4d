"""The obstacle bounds a world keeps equal the bounds read afresh, whatever moved."""

from __future__ import annotations

import numpy as np

from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.world import ObstacleBoxes, World


def _same(kept: ObstacleBoxes, fresh: ObstacleBoxes) -> bool:
    return (
        kept.names == fresh.names
        and kept.indices == fresh.indices
        and [o.name for o in kept.objects] == [o.name for o in fresh.objects]
        and np.array_equal(kept.low, fresh.low)
        and np.array_equal(kept.high, fresh.high)
    )


def test_kept_bounds_follow_what_moves() -> None:
    world = kitchen_scene("pr2").world
    skip = ["pr2", "floor"]
    first = world.contacts.obstacle_boxes(skip)
    assert _same(first, ObstacleBoxes.of(world, skip))
    assert world.contacts.obstacle_boxes(skip) is first  # nothing moved: the same table
    world.set_joint_states("pr2", {"torso_lift_joint": 0.2})  # skipped: still the same
    assert world.contacts.obstacle_boxes(skip) is first
    mug = world.pose("mug-1")
    world.set_pose("mug-1", Pose((mug.position[0] + 0.3, *mug.position[1:]), mug.orientation))
    moved = world.contacts.obstacle_boxes(skip)
    assert moved is not first and _same(moved, ObstacleBoxes.of(world, skip))
    world.set_joint_states("kitchen", {"drawer_unit_drawer_1_joint": 0.2})  # opened
    opened = world.contacts.obstacle_boxes(skip)
    assert _same(opened, ObstacleBoxes.of(world, skip)) and not _same(opened, moved)
    fewer = world.contacts.obstacle_boxes([*skip, "mug-1"])
    assert _same(fewer, ObstacleBoxes.of(world, [*skip, "mug-1"]))
    assert "mug-1" not in {o.name for o in fewer.objects}


def test_a_removed_object_leaves_the_kept_bounds() -> None:
    with World() as world:
        world.add_box("a", (0.2, 0.2, 0.2), Pose((0.0, 0.0, 0.1)))
        world.add_box("b", (0.2, 0.2, 0.2), Pose((1.0, 0.0, 0.1)))
        assert [o.name for o in world.contacts.obstacle_boxes().objects] == ["a", "b"]
        world.remove("b")
        assert [o.name for o in world.contacts.obstacle_boxes().objects] == ["a"]
        assert not world.contacts.obstacle_boxes().low.flags.writeable  # shared: read-only


def test_bounds_after_a_joint_moved_are_read_again_below_it_only() -> None:
    """A drawer opened a step: its links' rows move by the step, every other row stays,
    and the table equals one read afresh, also after the joint went back or the body's
    base moved."""
    world = kitchen_scene("pr2").world
    skip = ["pr2", "floor"]
    joint, link = "drawer_unit_drawer_1_joint", "drawer_unit_drawer_1"
    closed = world.contacts.obstacle_boxes(skip)
    world.set_joint_states("kitchen", {joint: 0.2})
    opened = world.contacts.obstacle_boxes(skip)
    assert _same(opened, ObstacleBoxes.of(world, skip))
    kitchen = [k for k, o in enumerate(opened.objects) if o.name == "kitchen"]
    moved = [k for k in kitchen if not np.array_equal(opened.low[k], closed.low[k])]
    assert opened.names.index(link) in moved
    step = opened.low[opened.names.index(link)] - closed.low[closed.names.index(link)]
    assert abs(float(np.linalg.norm(step)) - 0.2) < 1e-9  # moved by the drawer's travel
    assert 0 < len(moved) < len(kitchen) / 4  # the drawer's links only
    world.set_joint_states("kitchen", {joint: 0.0})
    assert _same(world.contacts.obstacle_boxes(skip), closed)  # back: the same bounds
    base = world.pose("kitchen")
    world.set_pose("kitchen", Pose((base.position[0] + 0.5, *base.position[1:]), base.orientation))
    world.set_joint_states("kitchen", {joint: 0.1})  # the base moved too: read whole
    assert _same(world.contacts.obstacle_boxes(skip), ObstacleBoxes.of(world, skip))


def test_the_colliders_of_a_link_set_follow_the_body_indexed() -> None:
    """The colliders kept per tuple of links are the ones read afresh, and are read again
    once the body is indexed anew (a restored body's shapes may differ)."""
    world = kitchen_scene("pr2").world
    pr2 = world.object("pr2")
    links = ("l_forearm_link", "l_gripper_palm_link", "l_gripper_tool_frame", "base_link")
    expected = {pr2.link_index[n]: n for n in links if pr2.link_index[n] in pr2.colliders}
    assert pr2.colliders_among(links) == expected
    assert "l_gripper_tool_frame" not in expected.values()  # a frame: no shape
    palm = pr2.link_index["l_gripper_palm_link"]
    pr2.forget_indices()  # as when the body is loaded again
    pr2.colliders = frozenset({palm})
    assert pr2.colliders_among(links) == {palm: "l_gripper_palm_link"}

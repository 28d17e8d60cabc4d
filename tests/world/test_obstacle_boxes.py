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

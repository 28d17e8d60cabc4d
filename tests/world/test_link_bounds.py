"""Bounds read once serve both contact queries of a configuration with the same answers,
and a check may set joints without carrying what the robot holds there and back."""

from __future__ import annotations

import pytest

from robocram.scenes import kitchen_scene
from robocram.world import World
from robocram.world.link_contacts import link_bounds, link_pairs_in_contact, self_contacts

REACHING = {"r_shoulder_pan_joint": -0.3, "r_shoulder_lift_joint": 0.2,
            "r_elbow_flex_joint": -0.4, "r_wrist_flex_joint": -0.5}  # fmt: skip
AT_THE_COUNTER = ((-1.4, 1.55, 0.0), (0.0, 0.0, 0.7071067811865475, 0.7071067811865476))


@pytest.fixture(scope="module")
def world() -> World:
    world = kitchen_scene("pr2").world
    world.set_pose("pr2", AT_THE_COUNTER)
    world.set_joint_states("pr2", REACHING)
    return world


def test_bounds_read_before_give_the_same_contacts(world: World) -> None:
    body = world.object("pr2")
    floors = world.objects(type="floor")
    bounds = link_bounds(world, body, body.collider_names())
    assert len(bounds) == len(body.colliders)
    fresh = link_pairs_in_contact(world, body, floors, 0.0)
    assert len(fresh) > 3  # the arm in the counter, the base at a handle
    assert link_pairs_in_contact(world, body, floors, 0.0, bounds=bounds) == fresh
    pairs = [(a, b) for a in ("r_forearm_link", "r_upper_arm_link")
             for b in ("base_link", "torso_lift_link", "l_forearm_link")]  # fmt: skip
    near = self_contacts(world, body, pairs, 0.05)
    assert self_contacts(world, body, pairs, 0.05, bounds) == near


def test_joints_set_without_carrying_leave_what_is_held(world: World) -> None:
    mug = world.pose("mug-1")
    world.attach("mug-1", "pr2", "r_gripper_palm_link")
    try:
        before = world.joint_states("pr2")
        world.set_joint_states("pr2", {"r_elbow_flex_joint": -1.0}, carry=False)
        assert world.pose("mug-1") == mug
        world.set_joint_states("pr2", {"r_elbow_flex_joint": before["r_elbow_flex_joint"]})
        assert world.pose("mug-1").position == pytest.approx(mug.position, abs=1e-9)
        world.set_joint_states("pr2", {"r_elbow_flex_joint": -1.0})
        assert world.pose("mug-1").position != pytest.approx(mug.position, abs=1e-3)
    finally:
        world.detach("mug-1")

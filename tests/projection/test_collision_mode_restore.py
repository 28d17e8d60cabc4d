"""An IK collision check leaves the robot as it was: joints and the values simulation
holds them at, while putting back only what it changed."""

from __future__ import annotations

from robocram.projection import ProjectedRobot
from robocram.projection.collision_mode import collision_check
from robocram.scenes import kitchen_scene


def test_a_check_puts_back_what_it_moved_and_names_the_same_contacts() -> None:
    world = kitchen_scene("pr2").world
    robot = ProjectedRobot.of(world, "pr2")
    world.set_joint_states("pr2", {"head_pan_joint": 0.3})  # held where it was set
    joints, held = world.joint_states("pr2"), world.snapshots.held_joints("pr2")
    check = collision_check(robot, "right", "avoid_all")
    assert check is not None
    reaching = {"r_shoulder_lift_joint": -0.3, "r_elbow_flex_joint": -0.2,
                "r_shoulder_pan_joint": 0.2}  # fmt: skip
    found = check(reaching)
    assert world.joint_states("pr2") == joints and world.snapshots.held_joints("pr2") == held
    world.set_joint_states("pr2", reaching)
    floors = [o for o in world.objects() if o.type == "floor"]
    touching = {(link, other.name) for link, other, _ in
                world.contacts.link_pairs_in_contact("pr2", floors)}  # fmt: skip
    assert {(link, other.split("/")[0]) for link, other in found} == touching

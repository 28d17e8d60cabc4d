"""An IK check reads the robot's start once per query: the links a candidate leaves in
place keep what they touch there, and self pairs touching at the start stay allowed. Every
candidate must still name exactly what a fresh check names."""

from __future__ import annotations

import pytest

from robocram.projection import ProjectedRobot
from robocram.projection.collision_mode import arm_pairs, collision_check, putting_back_once
from robocram.scenes import kitchen_scene
from robocram.world import World

ARM = ("r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
       "r_elbow_flex_joint", "r_forearm_roll_joint", "r_wrist_flex_joint",
       "r_wrist_roll_joint")  # fmt: skip
ON_THE_BASE = (-0.37, -0.01, -2.84, -2.28, 1.88, -0.18, 0.64)  # fingertips touch base_link
REACHING = (-0.3, 0.2, -0.5, -0.4, 0.0, -0.5, 0.0)
AT_THE_COUNTER = ((-1.4, 1.55, 0.0), (0.0, 0.0, 0.7071067811865475, 0.7071067811865476))


@pytest.fixture(scope="module")
def world() -> World:
    return kitchen_scene("pr2").world


def _fresh(robot: ProjectedRobot, candidate: dict[str, float]) -> list[tuple[str, str]]:
    check = collision_check(robot, "right", "avoid_all")
    assert check is not None
    return check(candidate)


def test_later_candidates_name_what_a_fresh_check_names(world: World) -> None:
    robot = ProjectedRobot.of(world, "pr2")
    world.set_pose("pr2", AT_THE_COUNTER)  # the base touches a drawer's handle
    joints, pose = world.joint_states("pr2"), world.pose("pr2")
    check = collision_check(robot, "right", "avoid_all")
    assert check is not None
    candidates = [
        dict(zip(ARM, ON_THE_BASE, strict=True)),
        dict(zip(ARM, REACHING, strict=True)),
        {**dict(zip(ARM, REACHING, strict=True)), "torso_lift_joint": 0.3},  # moves more
        dict(zip(ARM, (0.0,) * 7, strict=True)),
    ]
    seen = [check(candidate) for candidate in candidates]
    assert world.joint_states("pr2") == joints and world.pose("pr2") == pose
    assert seen == [_fresh(robot, candidate) for candidate in candidates]
    assert ("r_gripper_l_finger_tip_link", "base_link") in seen[0]
    assert all(("base_link", "kitchen/drawer_unit_drawer_1_handle") in s for s in seen)
    assert len(seen[1]) > 1 and len(seen[3]) > 1  # the arm in the counter too


def test_self_pairs_touching_at_the_start_stay_allowed(world: World) -> None:
    robot = ProjectedRobot.of(world, "pr2")
    world.set_pose("pr2", ((-0.8, 0.2, 0.0), (0.0, 0.0, 0.0, 1.0)))  # in the open
    on_base = dict(zip(ARM, ON_THE_BASE, strict=True))
    world.set_joint_states("pr2", on_base)
    touching = set(world.contacts.self_contacts("pr2", arm_pairs(robot, "right")))
    assert ("r_gripper_l_finger_tip_link", "base_link") in touching
    nudged = {**on_base, "r_wrist_roll_joint": 0.7}
    found = _fresh(robot, nudged)
    assert not touching & set(found)
    world.set_joint_states("pr2", dict(zip(ARM, REACHING, strict=True)))
    assert touching & set(_fresh(robot, nudged))  # from elsewhere, the same pose collides


def test_a_query_puts_the_robot_back_once_even_when_it_raises(world: World) -> None:
    robot = ProjectedRobot.of(world, "pr2")
    world.set_pose("pr2", AT_THE_COUNTER)
    joints, held = world.joint_states("pr2"), world.snapshots.held_joints("pr2")
    candidates = [
        dict(zip(ARM, REACHING, strict=True)),
        dict(zip(ARM, ON_THE_BASE, strict=True)),  # a self pair: put back to ask the start
        {**dict(zip(ARM, REACHING, strict=True)), "torso_lift_joint": 0.3},
        dict(zip(ARM, (0.0,) * 7, strict=True)),  # the torso goes back first
    ]
    check = collision_check(robot, "right", "avoid_all")
    assert check is not None
    with pytest.raises(RuntimeError), putting_back_once(check):
        seen = [check(candidate) for candidate in candidates]
        assert world.joint_states("pr2") != joints  # left at the last candidate
        raise RuntimeError("a stopped task")
    assert world.joint_states("pr2") == joints and world.snapshots.held_joints("pr2") == held
    assert seen == [_fresh(robot, candidate) for candidate in candidates]


def test_links_a_later_candidate_moves_are_read_again(world: World) -> None:
    robot = ProjectedRobot.of(world, "pr2")
    world.set_pose("pr2", ((-0.12, 1.4, 0.0), AT_THE_COUNTER[1]))
    left = (-0.71, 0.9, -0.38, -0.15, 0.66, -0.18, 0.1)  # the hand in the cutlery unit
    lefts = [j.replace("r_", "l_", 1) for j in ARM]
    world.set_joint_states("pr2", dict(zip(lefts, left, strict=True)))
    arm = dict(zip(ARM, (-0.94, 0.51, 0.08, -0.34, 0.58, -0.39, -0.09), strict=True))
    raised = {**arm, "torso_lift_joint": 0.3}  # the left hand rises with the torso
    check = collision_check(robot, "right", "avoid_all")
    assert check is not None
    seen = [check(arm), check(raised)]
    assert seen == [_fresh(robot, arm), _fresh(robot, raised)]
    hand = [{p for p in s if p[0].startswith("l_")} for s in seen]
    assert hand[0] and hand[1] and hand[0] != hand[1]

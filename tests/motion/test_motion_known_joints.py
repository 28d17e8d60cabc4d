"""A world checker writes no joints the robot already stands at, and forgets what it knew
as soon as anything else writes (the world's clock), so every check still stands where
it asked."""

from __future__ import annotations

from robocram.motion.bullet_scene import BulletScene
from robocram.motion.known_joints import KnownJoints
from robocram.world import RobotHandle, World

ARM = (
    "l_shoulder_pan_joint",
    "l_shoulder_lift_joint",
    "l_upper_arm_roll_joint",
    "l_elbow_flex_joint",
    "l_forearm_roll_joint",
    "l_wrist_flex_joint",
    "l_wrist_roll_joint",
)
MASTER = "l_gripper_l_finger_joint"  # the PR2's fingers follow it (mimic joints)
FOLLOWER = "l_gripper_r_finger_joint"


def _arm(world: World) -> list[float]:
    now = world.joint_states("pr2")
    return [now[j] for j in ARM]


def _moved(world: World, start: list[float]) -> list[float]:
    """``start`` 0.1 rad on in every joint, within the joints' limits (as a write clamps)."""
    limits = [world.bodies.joint_limits("pr2", j) for j in ARM]
    return [lim.clamp(v + 0.1) for lim, v in zip(limits, start, strict=True)]


def test_a_check_where_the_robot_stands_writes_nothing(kitchen: World) -> None:
    scene = BulletScene(RobotHandle.of(kitchen, "pr2"), ARM)
    start = _arm(kitchen)
    stamp = kitchen.versions.joints("pr2")
    scene.colliding(start)  # the start's contacts, as a motion asks them: posed and put back
    assert kitchen.versions.joints("pr2") == stamp  # no write, none to put back
    moved = _moved(kitchen, start)
    scene.colliding(moved)
    assert kitchen.versions.joints("pr2") != stamp  # a check elsewhere writes (and back)
    assert _arm(kitchen) == start


def test_another_write_makes_the_checker_write_again(kitchen: World) -> None:
    scene = BulletScene(RobotHandle.of(kitchen, "pr2"), ARM)
    start = _arm(kitchen)
    moved = _moved(kitchen, start)
    with scene.posed():
        scene.clearances(moved)
        assert _arm(kitchen) == moved
        kitchen.set_joint_states("pr2", dict(zip(ARM, start, strict=True)))  # another writer
        scene.clearances(moved)  # known values are stale: written again
        assert _arm(kitchen) == moved
    assert _arm(kitchen) == start  # put back once


def test_a_master_is_known_only_while_its_followers_follow(kitchen: World) -> None:
    held = kitchen.joint_states("pr2")[MASTER]
    kitchen.set_joint_states("pr2", {MASTER: 0.3})  # the followers with it
    try:
        known = KnownJoints(kitchen, "pr2", kitchen.robot("pr2").description.model)
        known.read(kitchen.joint_states("pr2"))
        stamp = kitchen.versions.joints("pr2")
        known.write({MASTER: 0.3})
        assert kitchen.versions.joints("pr2") == stamp  # it stands so: nothing written
        kitchen.set_joint_states("pr2", {FOLLOWER: 0.1})  # a follower set on its own
        known.read(kitchen.joint_states("pr2"))
        known.write({MASTER: 0.3})  # the master's write puts the follower back
        assert kitchen.versions.joints("pr2") != stamp
        assert abs(kitchen.joint_states("pr2")[FOLLOWER] - 0.3) < 1e-12
    finally:
        kitchen.set_joint_states("pr2", {MASTER: held})

"""The coal collision scene against PyBullet's own check, on the PR2, HSR and Boxy."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from robocram.motion import CollisionScene, joint_limits
from robocram.scenes import kitchen_scene, tabletop_scene
from robocram.tf import Pose
from robocram.world import RobotHandle, World

NEAR = 0.01  # [m] closer than this, the engines may disagree (hull margins, tolerances)


def _arm_joints(world: World, robot: str, arm: str) -> list[str]:
    desc = world.robot(robot).description
    torso = [desc.torso_joint] if desc.torso_joint else []
    return [*torso, *desc.arms[arm].joints]


def _start(world: World, robot: str, joints: list[str]) -> np.ndarray:
    states = world.joint_states(robot)
    return np.array([states[j] for j in joints])


def _samples(world: World, robot: str, joints: list[str], n: int, seed: int) -> np.ndarray:
    limits = joint_limits(world.robot(robot).description, joints)
    lower = np.array([max(lim.lower, -np.pi) for lim in limits])
    upper = np.array([min(lim.upper, np.pi) for lim in limits])
    return lower + np.random.default_rng(seed).random((n, len(joints))) * (upper - lower)


def _bullet_pairs(world: World, robot: str, distance: float) -> set[tuple[str, str]]:
    """PyBullet's (robot link, other) pairs within ``distance``, as colliding_pairs names them."""
    skip = [
        o for o in world.objects() if o.type == "floor" or o.name in world.bodies.attachments(robot)
    ]
    return {
        (link, obj.name if len(world.link_names(obj)) == 1 else f"{obj.name}/{other}")
        for link, obj, other in world.contacts.link_pairs_in_contact(robot, skip, distance)
    }


def _world_pairs(
    scene: CollisionScene, q: np.ndarray, robot_links: set[str]
) -> set[tuple[str, str]]:
    return {p for p in scene.colliding(q) if p[1] not in robot_links}


def _agreement(world: World, robot: str, joints: list[str], n: int, seed: int) -> dict[str, int]:
    scene = CollisionScene.of(RobotHandle.of(world, robot), joints)
    links = set(world.link_names(robot))
    counts = {"agree": 0, "colliding": 0, "near": 0, "missed_deep": 0}
    before = world.joint_states(robot)
    try:
        for q in _samples(world, robot, joints, n, seed):
            ours = bool(_world_pairs(scene, q, links))
            world.set_joint_states(robot, dict(zip(joints, q, strict=True)))
            theirs = bool(_bullet_pairs(world, robot, 0.0))
            counts["colliding"] += theirs
            if ours == theirs:
                counts["agree"] += 1
                continue
            counts["near"] += 1
            if theirs and not ours:  # coal says free: PyBullet's deepest penetration
                depth = min(
                    p.distance for p in world.contacts.contact_points(robot) if p.object_b != robot
                )
                if depth < -NEAR:
                    counts["missed_deep"] += 1
            elif not _bullet_pairs(world, robot, NEAR):
                counts["missed_deep"] += 1  # coal collides, PyBullet not even within 1 cm
    finally:
        world.set_joint_states(robot, before)
    return counts


@pytest.fixture(scope="module")
def kitchen():
    scene = kitchen_scene("pr2")
    yield scene
    scene.world.close()


def _at_counter(world: World, robot: str) -> None:
    """Stand the robot 0.45 m from the north counter's front, where its arm reaches in."""
    pose = world.pose(robot)
    world.set_pose(robot, Pose((pose.position[0], AT_COUNTER_Y, 0.0), pose.orientation))


AT_COUNTER_Y = 1.35  # [m] in map: the north counter's front is at y = 1.8


@pytest.mark.parametrize(
    ("make", "near_counter"),
    [(kitchen_scene, False), (kitchen_scene, True), (tabletop_scene, False)],
    ids=["kitchen", "kitchen-counter", "tabletop"],
)
def test_pr2_agrees_with_pybullet_on_random_right_arm_configurations(make, near_counter):
    scene = make("pr2")
    if near_counter:
        _at_counter(scene.world, scene.robot)
    try:
        joints = _arm_joints(scene.world, scene.robot, "right")
        counts = _agreement(scene.world, scene.robot, joints, 200, seed=21)
    finally:
        scene.world.close()
    print(make.__name__, near_counter, counts)
    assert counts["missed_deep"] == 0
    assert counts["agree"] >= 180  # the rest are within 1 cm of contact


def test_start_configuration_is_free(kitchen):
    joints = _arm_joints(kitchen.world, kitchen.robot, "right")
    scene = CollisionScene.of(RobotHandle.of(kitchen.world, kitchen.robot), joints)
    q0 = _start(kitchen.world, kitchen.robot, joints)
    assert scene.colliding(q0) == []
    assert scene.is_free(q0)
    assert scene.geometry_count < 150  # far kitchen parts are culled


def test_box_where_the_forearm_is_is_found_and_named(kitchen):
    world, robot = kitchen.world, kitchen.robot
    joints = _arm_joints(world, robot, "right")
    where = world.link_pose(robot, "r_forearm_link") * Pose((0.2, 0.0, 0.0))
    world.add_box("obstacle", (0.08, 0.08, 0.08), where.position)
    try:
        scene = CollisionScene.of(RobotHandle.of(world, robot), joints)
        q0 = _start(world, robot, joints)
        pairs = scene.colliding(q0)
        assert ("r_forearm_link", "obstacle") in pairs
        assert not scene.is_free(q0)
        assert ("r_forearm_link", "obstacle") in _bullet_pairs(world, robot, 0.0)
    finally:
        world.remove("obstacle")


def test_held_mug_hitting_the_counter_is_found_fingers_on_it_are_not(kitchen):
    world, robot = kitchen.world, kitchen.robot
    desc = world.robot(robot).description
    arm = desc.arms["right"]
    joints = _arm_joints(world, robot, "right")
    with world.snapshots.stored_state():
        _at_counter(world, robot)
        world.set_pose("mug-1", world.link_pose(robot, arm.tool_frame).position)
        world.attach("mug-1", robot, arm.end_effector_link)
        touching = {p.link_b for p in world.contacts.contact_points("mug-1", robot)}
        assert touching & set(arm.gripper_links)  # the fingers do touch the mug
        scene = CollisionScene.of(RobotHandle.of(world, robot), joints)
        q0 = _start(world, robot, joints)
        at_start = scene.colliding(q0)
        assert not any(b == "mug-1" for _, b in at_start)  # the fingers on it are fine
        hits = []
        for q in _samples(world, robot, joints, 400, seed=5):
            pairs = scene.colliding(q)
            if any(a == "mug-1" and b.startswith("kitchen") for a, b in pairs):
                hits.append((q, pairs))
        assert hits, "no sampled configuration pushed the held mug into the kitchen"
        q, pairs = hits[0]
        world.set_joint_states(robot, dict(zip(joints, q, strict=True)))
        bullet = [p for p in world.contacts.contact_points("mug-1", "kitchen") if p.distance < NEAR]
        assert bullet  # PyBullet sees the mug on the kitchen too
        assert not any(a in arm.gripper_links and b == "mug-1" for a, b in pairs)


def test_self_collision_of_the_right_arm_is_found(kitchen):
    world, robot = kitchen.world, kitchen.robot
    joints = _arm_joints(world, robot, "right")
    before = world.joint_states(robot)
    arms = world.robot(robot).description.arms.values()
    world.set_joint_states(robot, {j: 0.0 for arm in arms for j in arm.joints})  # stretched
    try:
        scene = CollisionScene.of(RobotHandle.of(world, robot), joints)
        q = _start(world, robot, joints)
        q[joints.index("r_shoulder_pan_joint")] = 0.7  # swung in across the chest
        q[joints.index("r_elbow_flex_joint")] = -0.2
        pairs = scene.colliding(q)
        links = set(world.link_names(robot))
        selfs = [(a, b) for a, b in pairs if b in links]
        assert selfs, pairs
        world.set_joint_states(robot, dict(zip(joints, q, strict=True)))
        gaps = [  # PyBullet finds one of those pairs touching too
            p.distance for a, b in selfs
            for p in world.contacts.contact_points(robot, robot, a, b, distance=NEAR)
        ]  # fmt: skip
        assert gaps and min(gaps) < NEAR
    finally:
        world.set_joint_states(robot, before)


def test_copy_and_pickle_give_the_same_answers(kitchen):
    joints = _arm_joints(kitchen.world, kitchen.robot, "right")
    scene = CollisionScene.of(RobotHandle.of(kitchen.world, kitchen.robot), joints)
    qs = _samples(kitchen.world, kitchen.robot, joints, 40, seed=3)
    answers = [scene.colliding(q) for q in qs]
    for other in (scene.copy(), pickle.loads(pickle.dumps(scene))):
        assert [other.colliding(q) for q in qs] == answers
        assert [other.is_free(q) for q in qs] == [not a for a in answers]


@pytest.mark.parametrize(("robot", "arm"), [("hsrb", "arm"), ("boxy", "left")])
def test_other_robots_build_a_scene_and_agree_at_start(robot, arm):
    scene = kitchen_scene(robot)
    try:
        world = scene.world
        joints = _arm_joints(world, scene.robot, arm)
        coal_scene = CollisionScene.of(RobotHandle.of(world, scene.robot), joints)
        q0 = _start(world, scene.robot, joints)
        links = set(world.link_names(scene.robot))
        ours = _world_pairs(coal_scene, q0, links)
        assert ours == _bullet_pairs(world, scene.robot, 0.0)
        assert coal_scene.is_free(q0) == (not coal_scene.colliding(q0))
    finally:
        scene.world.close()

"""A coal scene's pairs, decided per kind of owner and spread as masks, are the pairs a
plain pair-by-pair walk of the rules makes, in the same order; the shortcuts beside them
(reach balls met at once, requests left as pinocchio makes them) answer as before."""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest

from robocram.motion import CollisionScene
from robocram.motion.allowed_contacts import AllowedContacts, Other
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.hand_contact import HandContact
from robocram.motion.reach_bounds import Sphere, Spheres, reach_sphere, shape_sphere
from robocram.motion.scene_geometry import SceneGeometry, _checked, build_geometry
from robocram.motion.scene_snapshot import SceneSnapshot
from robocram.motion.self_collision import active_joints, adjacent_pairs, moving_group
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.world import RobotHandle
from robocram.world.link_contacts import box_table

AT_COUNTER_Y = 1.35  # [m] in map: the north counter's front is at y = 1.8, the arm reaches in


@pytest.fixture(scope="module")
def kitchen():
    scene = kitchen_scene("pr2")
    yield scene
    scene.world.close()


def _reference_pairs(snap: SceneSnapshot, geo: SceneGeometry) -> list[tuple[int, int]]:
    """The pairs by the rules themselves, one pair at a time (moving side first, partners
    in index order), the reach balls' overlap from the balls' own test."""
    owners, model = geo.owners, snap.description.model
    group = moving_group(model, active_joints(model, snap.joints))
    rules = AllowedContacts.of(snap.description, snap.allowed_links)
    with_geometry = {o.link for o in owners if o.kind == "robot"}
    adjacent = adjacent_pairs(model, with_geometry) | set(snap.skipped_self)
    hand = snap.hand
    pairs = []
    for i, a in enumerate(owners):
        if a.kind == "static" or not group[a.link]:
            continue
        for j, b in enumerate(owners):
            if i == j or not _checked(a, b, group, adjacent, rules):
                continue
            touch = hand is not None and a.kind == "robot" and b.kind == "static"
            if touch and hand is not None and hand.covers(a.link, b.label):
                continue
            if j < i and b.kind != "static" and group[b.link]:
                continue
            pairs.append((i, j))
    return pairs


def test_pairs_are_the_rules_pair_by_pair_with_a_held_mug_and_a_hand_on_the_counter(kitchen):
    world, robot = kitchen.world, kitchen.robot
    desc = world.robot(robot).description
    arm = desc.arms["right"]
    joints = [desc.torso_joint, *arm.joints]
    with world.snapshots.stored_state():
        pose = world.pose(robot)
        world.set_pose(robot, Pose((pose.position[0], AT_COUNTER_Y, 0.0), pose.orientation))
        world.set_pose("mug-1", world.link_pose(robot, arm.tool_frame).position)
        world.attach("mug-1", robot, arm.end_effector_link)
        hand = HandContact.of(arm.gripper_links, "kitchen")
        snap = SceneSnapshot.take(RobotHandle.of(world, robot), joints, hand=hand)
    geo = build_geometry(snap)
    made = [(int(p.first), int(p.second)) for p in geo.geometry.collisionPairs]
    expected = _reference_pairs(snap, geo)
    # the reach balls leave far static partners out: the made pairs are the rule's pairs
    # among those whose balls meet, checked here by each ball's own overlap test
    balls = _balls(snap, geo)
    near = [
        (i, j) for i, j in expected
        if geo.owners[j].kind != "static" or balls[i] is None or balls[j] is None
        or balls[i].overlaps(balls[j])
    ]  # fmt: skip
    assert made == near
    assert geo.pair_labels == [(geo.owners[i].label, geo.owners[j].label) for i, j in made]
    kinds = {geo.owners[j].kind for _, j in made}
    assert kinds == {"robot", "held", "static"}  # every kind of partner is exercised
    covered = [
        (i, j) for i, j in made
        if geo.owners[j].kind == "static" and hand.covers(geo.owners[i].link, geo.owners[j].label)
    ]  # fmt: skip
    assert not covered  # the fingers are never paired with the kitchen they may touch
    fingers = {i for i, o in enumerate(geo.owners) if o.link in hand.links}
    assert any(i in fingers and geo.owners[j].kind == "static" for i, j in made)  # but others


def _balls(snap: SceneSnapshot, geo: SceneGeometry) -> list[Sphere | None]:
    """Each geometry's ball as the build makes them: where a moving one can reach, a
    static one's shape; None for the robot's parts no planned joint moves."""
    kin, model = geo.kinematics, snap.description.model
    active = active_joints(model, snap.joints)
    group = moving_group(model, active)
    data = kin.model.createData()
    pin.forwardKinematics(kin.model, data, geo.q0)
    objects = geo.geometry.geometryObjects
    return [
        shape_sphere(objects[k].geometry, objects[k].placement) if owner.kind == "static"
        else reach_sphere(kin, data, objects[k], active, snap.margin)
        if owner.link and group[owner.link] else None
        for k, owner in enumerate(geo.owners)
    ]  # fmt: skip


def test_balls_met_at_once_answer_as_one_at_a_time():
    rng = np.random.default_rng(3)
    moving = Spheres.of([Sphere(rng.normal(0, 1, 3), float(r)) for r in rng.random(20)])
    others = [Sphere(rng.normal(0, 2, 3), float(r)) for r in rng.random(200) * 0.5]
    others.append(Sphere(np.zeros(3), math.inf))  # a half-space's ball
    met = moving.meet_each(others)
    assert met == [moving.meet(o) for o in others]
    assert any(met) and not all(met)
    empty = Spheres.of([])
    assert empty.meet_each(others) == [empty.meet(o) for o in others] == [False] * len(others)
    assert moving.meet_each([]) == []


@pytest.mark.parametrize("margin", [0.0, 0.015])
def test_scene_requests_ask_for_the_margin_and_no_contacts(kitchen, margin):
    world, robot = kitchen.world, kitchen.robot
    desc = world.robot(robot).description
    joints = [desc.torso_joint, *desc.arms["right"].joints]
    scene = CollisionScene.of(RobotHandle.of(world, robot), joints, margin=margin)
    requests = scene._geometry_data.collisionRequests
    assert len(requests) == scene.pair_count > 0
    assert all(r.security_margin == margin and not r.enable_contact for r in requests)


def test_bounds_read_flat_are_the_nested_reading():
    rng = np.random.default_rng(0)
    boxes = [(tuple(rng.random(3)), tuple(rng.random(3) + 1.0)) for _ in range(7)]
    assert np.array_equal(box_table(boxes), np.array(boxes, dtype=float).reshape(-1, 2, 3))
    assert box_table([]).shape == (0, 2, 3)


def test_a_judges_kept_verdicts_are_its_rules_answers(kitchen):
    world, robot = kitchen.world, kitchen.robot
    desc = world.robot(robot).description
    arm = desc.arms["right"]
    joints = [desc.torso_joint, *arm.joints]
    hand = HandContact.of(arm.gripper_links, "kitchen")
    with world.snapshots.stored_state():
        pose = world.pose(robot)
        world.set_pose(robot, Pose((pose.position[0], AT_COUNTER_Y, 0.0), pose.orientation))
        judge = BulletScene(RobotHandle.of(world, robot), joints, hand=hand)
        q0 = np.array([world.joint_states(robot)[j] for j in joints])
        rng = np.random.default_rng(7)
        for q in q0 + rng.normal(0.0, 0.4, (25, len(joints))):
            judge.clearances(q)
            judge.colliding(q)
        assert judge._verdicts  # pairs near the counter were judged
        for link, name, _, other_link, _ in judge._verdicts:
            obj = world.object(name)
            fresh = (judge._counts(link, obj, other_link), judge._bounded(link, obj, other_link))
            assert judge._verdict(link, obj, other_link) == fresh
        assert any(bounded for _, bounded in judge._verdicts.values())  # the hand's contact
        assert judge.anywhere() == [
            o for o in world.objects()
            if o.name != robot and judge.rules.allows_any_link(Other(o.name, o.type))
        ]  # fmt: skip

"""Public contact queries (filtered by link, within a distance) and attachment/hold state."""

from __future__ import annotations

from collections.abc import Iterator

import pybullet
import pytest

from robocram.tf import Pose
from robocram.world import (
    Attachment,
    ContactPoint,
    UnknownJointError,
    UnknownLinkError,
    UnknownObjectError,
    World,
)
from robocram.world.link_contacts import link_pairs_in_contact


@pytest.fixture
def world() -> Iterator[World]:
    with World() as w:
        w.add_box("a", (0.2, 0.2, 0.2), Pose((0.0, 0.0, 0.1)))
        w.add_box("b", (0.2, 0.2, 0.2), Pose((0.19, 0.0, 0.1)))  # 1 cm into a
        w.add_box("c", (0.2, 0.2, 0.2), Pose((0.0, 0.25, 0.1)))  # 5 cm from a
        yield w


def test_contact_points_are_signed_distances_between_named_bodies(world: World) -> None:
    points = world.contacts.contact_points("a", "b")
    assert points and all(isinstance(p, ContactPoint) for p in points)
    assert {(p.obj_a, p.obj_b) for p in points} == {("a", "b")}
    assert min(p.distance for p in points) == pytest.approx(-0.01, abs=1e-4)
    assert world.contacts.contact_points("a", "c") == []
    near = world.contacts.contact_points("a", "c", distance=0.06)
    assert min(p.distance for p in near) == pytest.approx(0.05, abs=1e-4)
    assert near[0].normal_on_b[1] == pytest.approx(-1.0, abs=1e-6)  # from c towards a


def test_contact_points_with_every_other_object(world: World) -> None:
    assert {p.obj_b for p in world.contacts.contact_points("a")} == {"b"}
    assert {p.obj_b for p in world.contacts.contact_points("a", distance=0.06)} == {"b", "c"}


def test_contact_points_filtered_by_link() -> None:
    with World() as world:
        world.add_robot("pr2")
        world.add_box("post", (0.05, 0.05, 0.3), Pose((0.0, 0.0, 0.15)))  # inside the base
        base = world.contacts.contact_points("pr2", "post", link_a="base_link")
        assert base and {p.link_a for p in base} == {"base_link"}
        assert world.contacts.contact_points("pr2", "post", link_a="head_tilt_link") == []
        with pytest.raises(UnknownLinkError, match="base_lnk"):
            world.contacts.contact_points("pr2", "post", link_a="base_lnk")


def test_points_of_some_links_are_the_whole_bodys_points_on_them() -> None:
    """A hand's links asked alone give the points Bullet gives for the whole robot on
    them (raw pybullet), in its order; an alias frame's points go by its link's name."""
    with World() as world:
        world.add_robot("pr2")
        hand = world.link_pose("pr2", "r_gripper_palm_link").position
        world.add_box("block", (0.1, 0.1, 0.1), Pose((hand[0] + 0.1, hand[1], hand[2])))
        links = {"r_gripper_palm_link", "r_gripper_l_finger_link", "r_gripper_r_finger_link"}
        cid, robot = world.physics.client(), world.object("pr2")
        names = {
            pybullet.getJointInfo(robot.body_id, i, physicsClientId=cid)[12].decode(): i
            for i in range(pybullet.getNumJoints(robot.body_id, physicsClientId=cid))
        }
        raw = pybullet.getClosestPoints(
            robot.body_id, world.object("block").body_id, 0.02, physicsClientId=cid
        )
        wanted = {names[n] for n in links}
        expected = [(p[3], p[8], tuple(p[7])) for p in raw if p[3] in wanted]
        points = world.contacts.links_contact_points("pr2", links, "block", distance=0.02)
        assert len(expected) >= 2  # the palm and a finger at least
        assert [(names[p.link_a], p.distance, p.normal_on_b) for p in points] == expected
        assert world.contacts.links_contact_points("pr2", {"head_tilt_link"}, "block") == []


def test_collisions_follow_what_moved_since_the_bounds_were_kept(world: World) -> None:
    """Collisions read the others' bounds kept with the world; an object moved since is
    read again: the answers are raw PyBullet's before and after the move."""
    cid = world.physics.client()

    def raw(name: str) -> set[str]:
        body = world.object(name).body_id
        return {
            o.name for o in world.objects()
            if o.name != name
            and pybullet.getClosestPoints(body, o.body_id, 0.002, physicsClientId=cid)
        }  # fmt: skip

    assert {o.name for o in world.contacts.collisions("a")} == raw("a") == {"b"}
    world.set_pose("c", Pose((0.0, 0.1995, 0.1)))  # now 0.5 mm from a
    assert {o.name for o in world.contacts.collisions("a")} == raw("a") == {"b", "c"}
    world.set_pose("b", Pose((0.5, 0.0, 0.1)))
    assert {o.name for o in world.contacts.collisions("a")} == raw("a") == {"c"}


def test_kept_bounds_leave_out_only_links_near_nothing() -> None:
    """Link pairs asked with the others' kept bounds are the broadphase's, in its order:
    only links whose bounds meet nothing go unasked."""
    with World() as world:
        world.add_robot("pr2")
        world.bodies.add_floor()
        hand = world.link_pose("pr2", "r_gripper_palm_link").position
        for k, dz in enumerate((-0.06, 0.0, 0.06)):  # three slabs through the hand
            world.add_box(f"slab{k}", (0.3, 0.3, 0.02), Pose((hand[0], hand[1], hand[2] + dz)))
        world.add_box("far", (0.1, 0.1, 0.1), Pose((3.0, 0.0, 0.05)))
        robot, floor = world.object("pr2"), world.object("floor")
        kept = world.contacts.obstacle_boxes(["pr2", "floor"])
        asked = link_pairs_in_contact(world, robot, [floor], 0.002)
        spared = link_pairs_in_contact(world, robot, [floor], 0.002, kept=kept)
        named = [(link, obj.name, other) for link, obj, other in spared]
        assert named == [(link, obj.name, other) for link, obj, other in asked]
        assert {"slab0", "slab1", "slab2"} <= {name for _, name, _ in named}


def test_attachments_are_public_state(world: World) -> None:
    world.attach("b", "a", "link0")
    [att] = world.bodies.all_attachments()
    assert (att.obj, att.robot, att.link) == ("b", "a", "link0")
    assert att.link_T_obj.position == pytest.approx((0.19, 0.0, 0.0), abs=1e-6)
    moved = Attachment("b", "a", "link0", Pose((0.0, 0.0, 0.3)))
    world.snapshots.set_attachments([moved])
    world.set_pose("a", Pose((1.0, 0.0, 0.1)))
    assert world.pose("b").position == pytest.approx((1.0, 0.0, 0.4), abs=1e-6)
    with pytest.raises(UnknownObjectError):
        world.snapshots.set_attachments([Attachment("nope", "a", "link0", Pose())])
    assert world.bodies.all_attachments() == [moved]  # a bad list changes nothing


def test_held_joints_are_public_state() -> None:
    with World() as world:
        world.add_robot("pr2")
        world.set_joint_states("pr2", {"torso_lift_joint": 0.2})
        assert world.snapshots.held_joints("pr2")["torso_lift_joint"] == pytest.approx(0.2)
        world.snapshots.set_held_joints("pr2", {"torso_lift_joint": 0.1})
        assert world.snapshots.held_joints("pr2") == {"torso_lift_joint": 0.1}
        world.physics.step()  # holding puts the joint at the held value
        assert world.joint_states("pr2")["torso_lift_joint"] == pytest.approx(0.1)
        with pytest.raises(UnknownJointError, match="base_footprint_joint"):
            world.snapshots.set_held_joints("pr2", {"base_footprint_joint": 0.0})


def test_insert_brings_back_a_removed_handle(world: World) -> None:
    box = world.object("c")
    world.remove(box)
    assert world.bodies.insert(box, Pose((2.0, 0.0, 0.1))) is box
    assert world.object("c") is box
    assert world.pose("c").position == pytest.approx((2.0, 0.0, 0.1), abs=1e-9)


def test_self_contacts_match_closest_points_of_every_pair() -> None:
    """The bounds test only prunes: the pairs found are those within ``distance``, asked
    about again after the arm moved (the pairs' rows are kept with the handle)."""
    with World() as world:
        pr2 = world.add_robot("pr2")
        links = world.link_names(pr2)
        arm = [link for link in links if link.startswith("r_") and "gripper" in link]
        pairs = [(a, b) for a in arm for b in links if not b.startswith("r_")]
        for elbow in (0.0, -2.0):
            world.set_joint_states(pr2, {"r_elbow_flex_joint": elbow})
            for distance in (0.0, 0.3):
                expected = [
                    (a, b) for a, b in pairs
                    if world.contacts.contact_points(pr2, pr2, a, b, distance=distance)
                ]  # fmt: skip
                assert world.contacts.self_contacts(pr2, pairs, distance) == expected
        assert expected  # the far distance finds some
        assert world.contacts.self_contacts(pr2, []) == []

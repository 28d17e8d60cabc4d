"""CRAM's ``allow_hand`` bounded: the hand touches only what it acts on, 5 mm at most.

A PR2 swings its right arm forward; a box is planted where its palm ends, at a depth
measured on PyBullet's raw closest points (``RawDistances``, not the planner's checker).
Touching a box that is not the named object is refused and the failure names the box;
the named object is refused deeper than 5 mm and allowed within it, and the trajectory
stores that allowance. Letting the hand touch anything (``allowed_links``, the old
``allow_hand``) accepts all of them: those were the faults issue 35 found.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pytest

from robocram.execution.failures import ManipulationPathBlocked
from robocram.motion import ContactAllowance, MotionSettings, plan_arm_motion
from robocram.motion.collision_modes import hand_links
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH, HandContact
from robocram.tf import Pose
from robocram.world import RawDistances, RobotHandle, World

PALM = "r_gripper_palm_link"
STRAIGHT = MotionSettings(plan=False)  # the straight segment only: a blocked one fails
TOLERANCE = 2e-4  # [m] how near the planted depth comes to the one asked for


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    world = World()
    world.bodies.add_floor()
    world.add_robot("pr2")
    for arm in world.robot("pr2").description.arms.values():
        world.set_joint_states("pr2", dict(arm.parking))
    world.add_box("cup", (0.02, 0.02, 0.02), Pose((2.0, 0.0, 0.01)))  # the named object
    world.add_box("block", (0.02, 0.02, 0.02), Pose((2.0, 1.0, 0.01)))  # another body
    yield world
    world.close()


def _goal(world: World) -> dict[str, float]:
    """The right arm parked, its shoulder lowered: the palm swings forward and down."""
    parked = dict(world.robot("pr2").description.arms["right"].parking)
    return {**parked, "r_shoulder_lift_joint": parked["r_shoulder_lift_joint"] + 0.4}


def _palm_at(world: World, joints: dict[str, float]) -> np.ndarray:
    world.set_joint_states("pr2", joints)
    low, high = world.contacts.link_aabb("pr2", PALM)
    return (np.array(low) + np.array(high)) / 2


def _plant(world: World, box: str, depth: float) -> float:
    """Put ``box`` ahead of where the palm ends, along its last move, ``depth`` [m] into it
    (measured on PyBullet's raw closest points, the arm set to the goal and put back);
    return the depth measured."""
    raw = RawDistances(world)
    start = world.joint_states("pr2")
    goal = _goal(world)
    before = {**goal, "r_shoulder_lift_joint": goal["r_shoulder_lift_joint"] - 0.02}
    last = _palm_at(world, before)
    end = _palm_at(world, goal)
    way = (end - last) / np.linalg.norm(end - last)
    ahead = 0.08  # [m] the box's centre ahead of the palm's, then moved along the way
    for _ in range(60):  # by the measured gap's error, until it is the depth asked for
        world.set_pose(box, Pose(tuple((end + way * ahead).tolist())))
        gap = raw.closest("pr2", PALM, box, box, reach=0.1)
        distance = gap.distance if gap is not None else 0.1
        if abs(distance + depth) < TOLERANCE / 4:
            break
        ahead -= distance + depth
    world.set_joint_states("pr2", start)
    return -distance


def _hand(world: World, touching: str) -> HandContact:
    return HandContact.of(hand_links(world.robot("pr2").description.arms["right"]), touching)


def _clear(world: World) -> None:
    world.set_pose("cup", Pose((2.0, 0.0, 0.01)))
    world.set_pose("block", Pose((2.0, 1.0, 0.01)))


def test_the_hand_touching_another_body_is_refused_and_named(world: World) -> None:
    depth = _plant(world, "block", 0.001)
    try:
        assert depth == pytest.approx(0.001, abs=TOLERANCE)
        goal = _goal(world)
        with pytest.raises(ManipulationPathBlocked) as info:
            plan_arm_motion(
                RobotHandle.of(world, "pr2"), goal, settings=STRAIGHT, hand=_hand(world, "cup")
            )
        assert (PALM, "block") in info.value.colliding_pairs
        assert "block" in str(info.value)
        links = hand_links(world.robot("pr2").description.arms["right"])
        anything = plan_arm_motion(
            RobotHandle.of(world, "pr2"), goal, allowed_links=links, settings=STRAIGHT
        )
        assert anything.path.waypoints[-1] == pytest.approx([goal[j] for j in anything.path.joints])
    finally:
        _clear(world)


def test_the_named_object_deeper_than_5_mm_is_refused(world: World) -> None:
    depth = _plant(world, "cup", 0.008)
    try:
        assert depth == pytest.approx(0.008, abs=TOLERANCE) and depth > HAND_CONTACT_DEPTH
        with pytest.raises(ManipulationPathBlocked) as info:
            plan_arm_motion(
                RobotHandle.of(world, "pr2"),
                _goal(world),
                settings=STRAIGHT,
                hand=_hand(world, "cup"),
            )
        assert (PALM, "cup") in info.value.colliding_pairs
    finally:
        _clear(world)


def test_the_named_object_within_5_mm_is_allowed_and_the_trajectory_stores_it(
    world: World,
) -> None:
    depth = _plant(world, "cup", 0.003)
    try:
        assert depth == pytest.approx(0.003, abs=TOLERANCE) and depth < HAND_CONTACT_DEPTH
        hand = _hand(world, "cup")
        motion = plan_arm_motion(
            RobotHandle.of(world, "pr2"), _goal(world), settings=STRAIGHT, hand=hand
        )
        stored = motion.trajectory.allowed_contacts
        assert ContactAllowance(PALM, "cup", HAND_CONTACT_DEPTH) in stored
        assert {a.other for a in stored} == {"cup"}  # the named object, nothing else
        assert {a.robot_side for a in stored} == hand.links
        assert {a.depth for a in stored} == {0.005}
    finally:
        _clear(world)

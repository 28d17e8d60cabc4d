"""A drive inside ``move_tcp`` keeps the hand to its bounded contact (issue 35).

The hand's links pass the base checker (they may stay round what they grasp), so the drive
is walked densely for the hand: touching anything else, or going deeper than the bound into
what it acts on, is a breach. Depths are read from PyBullet's raw closest points.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.motion import BASE_JOINTS, joint_limits, time_parameterize
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH, KEEP_DEPTH, HandContact, hand_at_start
from robocram.motion.hand_sweep import hand_breach
from robocram.world import RobotHandle, World

HAND = ("r_gripper_palm_link", "r_gripper_l_finger_link", "r_gripper_r_finger_link",
        "r_gripper_l_finger_tip_link", "r_gripper_r_finger_tip_link")  # fmt: skip


@pytest.fixture
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        w.add_robot("pr2")
        yield w


def _tip(world: World) -> tuple[float, float, float]:
    x, y, z = world.link_pose("pr2", "r_gripper_r_finger_tip_link").position
    return (x, y, z)


def _depth(world: World, box: str) -> float:
    return max(
        (-p.distance for p in world.contacts.contact_points("pr2", box) if p.link_a in HAND),
        default=0.0,
    )


def test_a_hand_starting_deeper_than_its_bound_is_bounded_at_that_depth(world: World) -> None:
    x, y, z = _tip(world)
    world.add_box("box", (0.02, 0.02, 0.02), (x, y, z))
    hand = HandContact.of(HAND, "box")
    seen = set()
    for k in range(40):  # the box slides off the fingertip, 1 mm at a time
        world.set_pose("box", (x, y - 0.001 * k, z))
        deep = _depth(world, "box")
        bounded = hand_at_start(world, "pr2", hand)
        assert bounded is not None
        if deep + KEEP_DEPTH <= HAND_CONTACT_DEPTH:
            assert bounded is hand
            seen.add("within")
        else:
            assert bounded.depth == pytest.approx(deep + KEEP_DEPTH, abs=2e-4)
            seen.add("deeper")
    assert seen == {"within", "deeper"}


def test_a_drive_sweeping_the_hand_through_a_box_it_does_not_act_on_is_a_breach(
    world: World,
) -> None:
    x, y, z = _tip(world)
    world.add_box("box", (0.05, 0.05, 0.05), (x + 0.3, y, z))  # ahead of the hand
    world.add_box("mug", (0.05, 0.05, 0.05), (x - 0.5, y, z))  # what the hand acts on
    limits = joint_limits(world.robot("pr2").description, BASE_JOINTS)
    drive = time_parameterize("pr2", BASE_JOINTS, [(0.0, 0.0, 0.0), (0.4, 0.0, 0.0)], limits)
    found = hand_breach(RobotHandle.of(world, "pr2"), drive, HandContact.of(HAND, "mug"))
    assert found is not None and found.other == "box" and found.bound == 0.0
    assert 0.0 < found.time < drive.duration
    world.set_pose("pr2", (found_x := 0.0, 0.0, 0.0))
    assert world.pose("pr2").position[0] == found_x  # put back where it stood
    back = time_parameterize("pr2", BASE_JOINTS, [(0.0, 0.0, 0.0), (-0.2, 0.0, 0.0)], limits)
    assert hand_breach(RobotHandle.of(world, "pr2"), back, HandContact.of(HAND, "mug")) is None

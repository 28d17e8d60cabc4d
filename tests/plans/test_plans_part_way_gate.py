"""Which failed grasps the part-way retry takes up again (``pick_object._finger_caught``).

Opening the hand part way narrows its fingers only. Boxy's bowl tries in the default
kitchen were refused for its palm (``left_gripper_base_link``) as well as a finger: the
retry, offered them, took bowl-1 from a stand Boxy used to leave
(``test_plans_boxy_breakfast_causes.py``). In the kitchen batch's variant 27 the PR2's
right hand could not open where it stood (a finger met the stove): the retry opens the
hand fully first, and failed so 6 times. Clearing household 0's table, the Stretch's
fingertips closing on a spoon ended in the table top (the closing's goal in collision):
from any opening they end there, and 24 retries failed so. The pairs below are those the
runs refused, on the robots' own link lists.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.execution.failures import (
    GripperMetOneSide,
    GripperPathBlocked,
    ManipulationPoseUnreachable,
)
from robocram.plans.known_robot import current_robot
from robocram.plans.pick_object import _finger_caught
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
DRAWER = "kitchen/drawer_unit_drawer_3"


def _refused(*pairs: tuple[str, str]) -> ManipulationPoseUnreachable:
    return ManipulationPoseUnreachable("refused in collision", colliding_pairs=pairs)


@pytest.mark.parametrize(
    ("robot", "arm", "palm", "finger"),
    [
        ("boxy", "left", "left_gripper_base_link", "left_gripper_finger_right_link"),
        (STRETCH, "arm", "link_straight_gripper", "link_gripper_fingertip_right"),
    ],
)
def test_a_finger_alone_of_the_hand_caught_is_retried_a_palm_with_it_is_not(
    robot: str, arm: str, palm: str, finger: str
) -> None:
    scene = kitchen_scene(robot)
    try:
        with simulated_robot(scene.world, scene.robot):
            known = current_robot()
            assert palm in known.hand_links(arm) and palm not in known.gripper_links(arm)
            only_finger = _refused((finger, DRAWER), ("base_link", "kitchen/drawer_unit_body"))
            with_palm = _refused((palm, DRAWER), (finger, DRAWER))
            assert _finger_caught(known, arm, only_finger, opened=True)
            assert not _finger_caught(known, arm, with_palm, opened=True)
            assert not _finger_caught(known, arm, _refused(("base_link", DRAWER)), opened=True)
            one_sided = GripperMetOneSide("one side", gripper=arm, met="bowl-1")
            assert _finger_caught(known, arm, one_sided, opened=True)
    finally:
        scene.world.close()


def test_a_hand_that_could_not_open_where_it_stood_is_not_retried() -> None:
    scene = kitchen_scene("pr2")
    try:
        with simulated_robot(scene.world, scene.robot):
            known = current_robot()
            blocked = GripperPathBlocked(
                "pr2's right gripper cannot move to 0.548",
                gripper="right",
                goal=0.548,
                colliding_pairs=(("r_gripper_r_finger_link", "kitchen/stove"),),
            )
            assert not _finger_caught(known, "right", blocked, opened=False)
            assert _finger_caught(known, "right", blocked, opened=True)  # closing, say
    finally:
        scene.world.close()


def test_a_closing_whose_end_is_in_collision_is_not_retried_one_blocked_on_its_way_is() -> None:
    scene = kitchen_scene(STRETCH)
    try:
        with simulated_robot(scene.world, scene.robot):
            known = current_robot()
            tips = (
                ("link_gripper_fingertip_right", "kitchen/table_top"),
                ("link_gripper_fingertip_left", "kitchen/table_top"),
            )
            on_the_table = GripperPathBlocked(
                "goal configuration in collision", gripper="arm", goal=0.087,
                colliding_pairs=tips, path_fraction=1.0,
            )  # fmt: skip
            at_the_bowl = GripperPathBlocked(
                "straight path blocked 3% of the way", gripper="arm", goal=0.017,
                colliding_pairs=(("link_gripper_fingertip_right", "bowl-2"),), path_fraction=0.03,
            )  # fmt: skip
            assert not _finger_caught(known, "arm", on_the_table, opened=True)
            assert _finger_caught(known, "arm", at_the_bowl, opened=True)
    finally:
        scene.world.close()

"""tabletop_scene takes a name or any description; bad input says what is missing, briefly."""

from __future__ import annotations

from dataclasses import replace

import pytest

from robocram.robots import DescriptionCheckError
from robocram.robots.builtin import builtin_description
from robocram.scenes import UnfitRobotError, tabletop_scene
from robocram.world import World

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")


def test_a_description_without_a_gripper_says_what_to_give() -> None:
    desc = builtin_description("hsrb")
    arm = replace(desc.arms["arm"], gripper_joints=(), gripper_links=())
    with World() as world, pytest.raises(UnfitRobotError) as info:
        tabletop_scene(replace(desc, name="my_hsr", arms={"arm": arm}), world)
    text = str(info.value)
    assert text.startswith("cannot build the scene for 'my_hsr': it has no arm with joints")
    assert "give an ArmDescription joints (or a base_link) and gripper_joints" in text
    assert "RobotDescription(" not in text and len(text) < 300


def test_something_else_than_a_robot_is_a_type_error_naming_its_type() -> None:
    with pytest.raises(
        TypeError, match=r"robot name, a description file or a RobotDescription, got a dict$"
    ):
        tabletop_scene({"name": "pr2"})  # type: ignore[arg-type]


def test_a_description_with_a_typo_fails_before_the_scene_with_a_suggestion() -> None:
    desc = builtin_description("pr2")
    with pytest.raises(DescriptionCheckError, match=r"did you mean 'torso_lift_joint'"):
        tabletop_scene(replace(desc, torso_joint="torso_lift_jont"))

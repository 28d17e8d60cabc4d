"""An arm that cannot reach says what collides and advises only what applies to the robot."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import ManipulationPoseUnreachable
from robocram.projection import simulated_robot
from robocram.robots.builtin import builtin_description
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.tf import PoseStamped

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")

DOWN = (0.0, 0.7071068, 0.0, 0.7071068)  # tool x axis (approach) pointing down


@pytest.fixture
def hsrb() -> Iterator[TabletopScene]:
    scene = tabletop_scene("hsrb")
    yield scene
    scene.world.close()


def failure(scene: TabletopScene, arm: str, target: PoseStamped, **keys: str) -> str:
    with (
        simulated_robot(scene.world, scene.robot),
        pytest.raises(ManipulationPoseUnreachable) as info,
    ):
        perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=target), **keys))
    return str(info.value)


def into_mug(scene: TabletopScene) -> PoseStamped:
    """The tool frame inside the mug, pointing down: the hand must touch it."""
    x, y, z = scene.world.pose("mug-1").position
    return PoseStamped("map", (x, y, z + 0.05), DOWN)


def test_a_hand_hitting_the_object_is_named_with_allow_hand_advice(hsrb: TabletopScene) -> None:
    text = failure(hsrb, "arm", into_mug(hsrb))
    assert "solutions rejected in collision (robot link-object: hand_" in text
    assert "-mug-1" in text
    assert "allow it with collision_mode='allow_hand'" in text
    assert "other arm" not in text and "move the base" not in text  # one arm, in reach


def test_an_arm_link_hitting_the_table_advises_another_approach(hsrb: TabletopScene) -> None:
    x, y, z = hsrb.world.pose("mug-1").position
    text = failure(
        hsrb, "arm", PoseStamped("map", (x, y, z - 0.1), DOWN), collision_mode="allow_hand"
    )
    assert "-table" in text and "approach from another side" in text
    assert "other arm" not in text


def test_out_of_reach_says_by_how_much_and_one_arm_gets_no_other_arm(hsrb: TabletopScene) -> None:
    text = failure(hsrb, "arm", PoseStamped("base_footprint", (3.0, 0.0, 0.8)))
    assert "the target lies 2.27" in text and "m beyond the arm's reach" in text
    assert "move the base at least 2.27" in text
    assert "other arm" not in text and "rejected" not in text


def test_a_two_armed_robot_out_of_reach_is_told_to_try_the_other_arm() -> None:
    scene = tabletop_scene("pr2")
    text = failure(scene, "right", PoseStamped("base_footprint", (3.0, 0.0, 0.8)))
    assert "move the base at least" in text and "or use the other arm (left)" in text
    scene.world.close()


def test_a_finger_left_out_of_hand_links_is_named_in_allow_hand_mode() -> None:
    desc = builtin_description("hsrb")
    palm_only = ("hand_palm_link",)
    arm = replace(desc.arms["arm"], hand_links=palm_only, gripper_links=palm_only)
    scene = tabletop_scene(replace(desc, arms={"arm": arm}))
    text = failure(scene, "arm", into_mug(scene), collision_mode="allow_hand")
    assert "hang below the wrist but are not in the arm arm's hand_links" in text
    assert "hand_l_distal_link" in text or "hand_r_distal_link" in text
    scene.world.close()


def test_a_target_behind_the_arm_advises_turning_the_base_and_the_other_arm() -> None:
    scene = tabletop_scene("pr2")
    behind = PoseStamped("base_footprint", (-0.45, -0.2, 0.9))
    text = failure(scene, "right", behind, collision_mode="allow_all")
    # 0.3 m: IK keeps to the PR2's soft limits (its URDF's safety_controller)
    assert "best IK configuration misses by 0.3" in text
    assert "the joint limits keep the tool 0.3" in text and "turn or move the base" in text
    assert "lies in front of the arm; or use the other arm (left)" in text
    assert "move the base at least" not in text and "rejected" not in text
    scene.world.close()

"""Action designators in the kitchen: keys checked, containers opened by what the KB says."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest

from robocram.costmaps import CostmapLocations
from robocram.designators import DesignatorPropertyError, an, using_location_resolver
from robocram.execution import perform
from robocram.plans import PlanSetupError, install_actions
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

HANDLE = "drawer_unit_drawer_3_handle"  # the top drawer, with the bowl in it


@pytest.fixture()
def pr2_kitchen() -> Iterator[KitchenScene]:
    scene = kitchen_scene("pr2")
    install_actions(scene.world.kb)
    yield scene
    scene.world.close()


def _in_front_of_the_drawer(scene: KitchenScene) -> Pose:
    handle_x = scene.world.link_pose("kitchen", HANDLE).position[0]
    return Pose((handle_x - 0.19, 0.95, 0.0), quat.from_euler(0.0, 0.0, math.pi / 2))


def test_open_and_close_a_drawer_by_its_handle(pr2_kitchen: KitchenScene) -> None:
    world = pr2_kitchen.world
    joint = "drawer_unit_drawer_3_joint"
    bowl_y = world.pose("bowl-1").position[1]
    with simulated_robot(world, pr2_kitchen.robot):
        perform(an.action(type="parking-arms"))
        perform(an.action(type="navigating", target=_in_front_of_the_drawer(pr2_kitchen)))
        opened = perform(an.action(type="opening", object=HANDLE, distance=0.3))
        assert world.joint_states("kitchen")[joint] == pytest.approx(0.3, abs=0.01)
        assert opened == pytest.approx(0.3, abs=0.01)
        assert world.pose("bowl-1").position[1] == pytest.approx(bowl_y - 0.3, abs=0.01)
        perform(an.action(type="closing", object="drawer_unit_drawer_3"))
        perform(an.action(type="parking-arms"))
    assert world.joint_states("kitchen")[joint] == pytest.approx(0.0, abs=0.01)
    assert world.pose("bowl-1").position[1] == pytest.approx(bowl_y, abs=0.01)


def test_opening_without_a_distance_opens_as_far_as_the_kb_says(
    pr2_kitchen: KitchenScene,
) -> None:
    world = pr2_kitchen.world
    with simulated_robot(world, pr2_kitchen.robot):
        perform(an.action(type="parking-arms"))
        perform(an.action(type="navigating", target=_in_front_of_the_drawer(pr2_kitchen)))
        perform(an.action(type="opening", object=HANDLE))
    opened = world.kb.first("container_opening(kitchen, drawer_unit_drawer_3, V)")
    assert opened is not None
    assert world.joint_states("kitchen")["drawer_unit_drawer_3_joint"] == pytest.approx(
        opened["V"], abs=0.01
    )


@pytest.mark.parametrize(
    ("properties", "culprit"),
    [
        ({"type": "opening", "object": HANDLE, "distanse": 0.3}, "distanse"),
        ({"type": "opening", "distance": 0.3}, "object"),
        ({"type": "moving-torso"}, "joint_angle"),
    ],
)
def test_a_wrong_or_missing_key_names_itself_and_the_valid_keys(
    pr2_kitchen: KitchenScene, properties: dict[str, object], culprit: str
) -> None:
    with (
        simulated_robot(pr2_kitchen.world, pr2_kitchen.robot),
        pytest.raises(DesignatorPropertyError, match="valid keys") as caught,
    ):
        perform(an.action(**properties))
    assert caught.value.key == culprit


def test_a_name_that_is_no_container_lists_the_containers(pr2_kitchen: KitchenScene) -> None:
    with (
        simulated_robot(pr2_kitchen.world, pr2_kitchen.robot),
        pytest.raises(PlanSetupError, match="'oven'.*drawer_unit_drawer_3"),
    ):
        perform(an.action(type="opening", object="oven"))


def test_searching_is_an_action_too(pr2_kitchen: KitchenScene) -> None:
    locations = CostmapLocations(pr2_kitchen.world, seed=0)
    with (
        simulated_robot(pr2_kitchen.world, pr2_kitchen.robot),
        using_location_resolver(locations.resolver()),
    ):
        seen = perform(an.action(type="searching", object=an.object(type="cereal_box")))
    assert seen.get("name") == "cereal-1"
    assert pr2_kitchen.world.view.visible(pr2_kitchen.robot, "cereal-1")

"""``reachable_for`` stands are stands the pick works from: its grasps, pre-grasp, collisions."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest

from robocram.costmaps import CostmapLocations, reach_object
from robocram.costmaps.stand_reach import reach_to_pick
from robocram.costmaps.validators import STAND_IK_RESTARTS, parked
from robocram.designators import a, an
from robocram.execution import perform
from robocram.plans import install_actions, pick_up_object, place_object
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose, PoseStamped
from robocram.world import RobotObject, World
from robocram.world.link_contacts import link_contacts


@pytest.fixture(scope="module", params=["pr2", "hsrb", "boxy"])
def scene(request: pytest.FixtureRequest) -> Iterator[KitchenScene]:
    built = kitchen_scene(request.param)
    install_actions(built.world.kb)
    yield built
    built.world.close()


def test_the_pick_works_from_the_stands_given(scene: KitchenScene) -> None:
    world, robot = scene.world, scene.robot
    start = world.pose("mug-1")
    for seed in range(3):
        with world.snapshots.stored_state():
            locations = CostmapLocations(world, seed=seed)
            with simulated_robot(world, robot, locations=locations):
                stand = a.location(reachable_for=robot, object="mug-1").reference()
                perform(an.action(type="parking-arms"))
                perform(an.action(type="navigating", target=stand))
                held = pick_up_object("mug-1")
                assert held.object_name == "mug-1"
                assert world.pose("mug-1").position[2] > start.position[2] + 0.05  # lifted


def test_a_stand_whose_pre_grasp_is_blocked_is_refused(scene: KitchenScene) -> None:
    world, robot = scene.world, world_robot(scene)
    mug = world.object("mug-1")
    stand = next(CostmapLocations(world).poses(a.location(reachable_for=robot.name, object=mug)))
    low, high = world.aabb(mug)
    centre = ((low[0] + high[0]) / 2, (low[1] + high[1]) / 2)
    world.kb.consult("object_grasps(mug, [top]).", group="only_top")  # the pick: top only
    try:
        with parked(world, robot):  # as the validator judges it: arms parked
            if reach_to_pick(world, robot, mug, stand, restarts=STAND_IK_RESTARTS) is None:
                pytest.skip(f"{robot.name} does not take the mug from the top from this stand")
            # a shelf board 7.5 cm over the mug, through the hand at the pre-grasp (its tool
            # 6 cm over the mug: the top grasp is 4 cm under the top): IK reaches through
            # it, the hand and arm do not
            board = world.add_box("board", (0.5, 0.5, 0.01), Pose((*centre, high[2] + 0.075)))
            try:
                assert reach_object(world, robot, mug, stand) is not None  # IK alone: yes
                assert reach_to_pick(world, robot, mug, stand, restarts=STAND_IK_RESTARTS) is None
            finally:
                world.remove(board)
    finally:
        world.kb.consult("", group="only_top")


def test_broadphase_contacts_agree_with_closest_points(scene: KitchenScene) -> None:
    world, robot = scene.world, world_robot(scene)
    floors = world.objects(type="floor")
    counter = world.pose("mug-1").position
    for dx in (-1.0, -0.6, -0.3, 0.0):
        with world.snapshots.stored_state():
            world.set_pose(robot, Pose((counter[0] + dx, counter[1] - 0.5, 0.0)))
            expected = {o.name for o in world.contacts.collisions(robot, floors)}
            found = {other for _, other in link_contacts(world, robot, ignore=floors)}
            assert found == expected


def world_robot(scene: KitchenScene) -> RobotObject:
    return scene.world.robot(scene.robot)


def test_the_place_works_from_the_stands_given(scene: KitchenScene) -> None:
    world, robot = scene.world, scene.robot
    with world.snapshots.stored_state(), simulated_robot(world, robot):
        spot = _near_the_edge(world)
        stand = a.location(reachable_for=robot, object="mug-1").reference()
        perform(an.action(type="parking-arms"))
        perform(an.action(type="navigating", target=stand))
        held = pick_up_object("mug-1")
        for seed in range(2):
            with world.snapshots.stored_state():
                locations = CostmapLocations(world, seed=seed)
                there = next(locations.poses(a.location(reachable_for=robot, target=spot.position)))
                perform(an.action(type="navigating", target=there))
                put = place_object(held, PoseStamped.from_pose("map", spot))  # its frame there
                assert math.dist(put.pose.position[:2], spot.position[:2]) < 0.03  # [m]
                table_top = world.contacts.link_aabb("kitchen", "table_top")[1][2]
                assert world.aabb("mug-1")[0][2] == pytest.approx(table_top, abs=0.01)


def _near_the_edge(world: World) -> Pose:
    """A place for the mug on the table near its north edge, where robots stand."""
    edge = world.contacts.link_aabb("kitchen", "table_top")[1][1]
    places = CostmapLocations(world).poses(a.location(on=("kitchen", "table_top"), for_="mug-1"))
    return next(p for p in places if p.position[1] > edge - 0.2)

"""Where the HSR stands to grasp: its five-joint arm may adjust the base, as when grasping."""

from __future__ import annotations

import dataclasses
import math

from robocram.costmaps import CostmapLocations, reach_object
from robocram.costmaps.reach_reasoning import blocking
from robocram.costmaps.validators import STAND_TRAVEL
from robocram.designators import a, using_location_resolver
from robocram.scenes import kitchen_scene


def test_the_hsr_finds_a_stand_to_grasp_the_mug_on_the_counter() -> None:
    scene = kitchen_scene("hsrb")
    world = scene.world
    robot = world.robot(scene.robot)
    locations = CostmapLocations(world, seed=0)
    with using_location_resolver(locations.resolver()):
        stand = a.location(reachable_for=scene.robot, object="mug-1").reference()
    mug = world.pose("mug-1").position
    assert math.dist(stand.position[:2], mug[:2]) < 1.0
    reach = reach_object(world, robot, world.object("mug-1"), stand)
    assert reach is not None and reach.base_motion is not None
    assert abs(reach.base_motion.x) <= STAND_TRAVEL.travel_x + 1e-9
    assert abs(reach.base_motion.y) <= STAND_TRAVEL.travel_y + 1e-9
    assert abs(reach.base_motion.yaw) <= STAND_TRAVEL.travel_yaw + 1e-9
    still = dataclasses.replace(robot.description.arms["arm"], base_in_ik=False)
    fixed = dataclasses.replace(robot.description, arms={"arm": still})
    alone = dataclasses.replace(robot, description=fixed)
    assert reach_object(world, alone, world.object("mug-1"), stand) is None
    start = world.pose(robot)
    world.set_pose(robot, stand)
    assert blocking(world, robot, "arm", "mug-1") is not None  # judged with the base moved
    assert world.pose(robot).distance_to(stand) < 1e-9
    world.set_pose(robot, start)
    world.close()

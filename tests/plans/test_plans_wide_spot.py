"""A bowl turned off the map's axes finds its table spot in the wider square (session 25,
Boxy's household seeds 7 and 9: bowl-1 held 16 degrees turned had no cell in the 0.3 m
square), the spot judged by raw PyBullet (the table's top under it)."""

from __future__ import annotations

import math

import pybullet
import pytest

from robocram.costmaps.errors import LocationNotFound
from robocram.plans.location_poses import location_poses
from robocram.plans.table_arrangement import SHARED, STANDARD_SETTING, spots, table_with_seats
from robocram.plans.table_trips import WIDE_SPOT_AREA, spot_location
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

TURN = -2.886  # [rad] bowl-1's heading in Boxy's hand in seed 7
SPOT_NEAR = 0.02  # [m] the `at` key keeps cells this near the spot


def test_a_turned_bowl_finds_its_spot_in_the_wide_square_only() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    try:
        with simulated_robot(world, scene.robot):
            table = table_with_seats(None)
            bowl = next(s for s in spots(table, 2, STANDARD_SETTING, SHARED) if s.type == "bowl")
            here = world.pose(world.object("bowl-1")).position
            world.set_pose(world.object("bowl-1"), Pose(here, quat.from_euler(0.0, 0.0, TURN)))
            with pytest.raises(LocationNotFound):
                next(location_poses(spot_location(table, bowl, "bowl-1")))
            found = next(location_poses(spot_location(table, bowl, "bowl-1", size=WIDE_SPOT_AREA)))
        x, y, _ = bowl.pose.position
        assert math.hypot(found.position[0] - x, found.position[1] - y) <= SPOT_NEAR + 0.01
        cid = world.physics.client()
        kitchen = world.object("kitchen")
        top = pybullet.getAABB(kitchen.body_id, kitchen.link_index["table_top"], cid)[1][2]
        assert found.position[2] >= top  # on the table's top, not in it
    finally:
        world.close()

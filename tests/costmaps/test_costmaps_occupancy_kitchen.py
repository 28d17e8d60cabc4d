"""Occupancy in the kitchen: walls taller than the robot block, and what moved is seen anew."""

from __future__ import annotations

import math

import numpy as np
import pytest

from robocram.costmaps import CostmapLocations
from robocram.costmaps.occupancy import footprint_radii, footprint_radius, occupancy_cost
from robocram.designators import a
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat


def test_no_cell_near_a_wall_is_free() -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    locations = CostmapLocations(world)
    query = locations.query(a.location(visible_for="pr2", target=(0.0, -1.8, 0.8)))
    free = occupancy_cost(query, None, np.ones(query.grid.shape, dtype=bool)).weights
    radius, outer = footprint_radii(world, world.robot("pr2"))
    _, y = query.centres()
    low, high = world.contacts.link_aabb("kitchen", "wall_south")
    # the PR2's base is 0.668 m square: half that inside, the corners 0.47 m out
    assert radius == pytest.approx(0.334, abs=0.01) and outer == pytest.approx(0.472, abs=0.01)
    assert high[2] > 1.9  # a 2 m wall: probes from the robot's top missed it
    assert not free[(y > low[1] - radius) & (y < high[1] + radius)].any()
    assert free[(y > high[1] + radius + 0.05) & (y < high[1] + radius + 0.3)].any()
    world.close()


def test_the_footprint_does_not_grow_when_the_robot_turns() -> None:
    scene = kitchen_scene("pr2")
    world, robot = scene.world, scene.world.robot("pr2")
    straight = footprint_radius(world, robot)
    world.set_pose(robot, Pose((0.0, 0.0, 0.0), quat.from_euler(0.0, 0.0, math.pi / 4)))
    assert footprint_radius(world, robot) == pytest.approx(straight, abs=1e-9)
    turned = quat.from_euler(0.0, 0.0, math.pi / 4)
    assert quat.angle_between(world.pose(robot).orientation, turned) < 1e-9  # put back
    world.close()


def test_a_crate_put_down_rules_out_the_cells_around_it_until_taken_away() -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    query = CostmapLocations(world).query(a.location(visible_for="pr2", target=(0.0, 0.0, 0.8)))
    everywhere = np.ones(query.grid.shape, dtype=bool)
    before = occupancy_cost(query, None, everywhere).weights
    x, y = query.centres()
    spot = (-1.5, 0.3)  # [m] open floor between the table and the counter
    near = np.hypot(x - spot[0], y - spot[1]) < 0.3
    assert before[near].all()
    crate = world.add_box("crate", (0.2, 0.2, 0.4), Pose((*spot, 0.2)))
    blocked = occupancy_cost(query, None, everywhere).weights
    assert not blocked[near].any()
    world.remove(crate)
    assert np.array_equal(occupancy_cost(query, None, everywhere).weights, before)
    world.close()

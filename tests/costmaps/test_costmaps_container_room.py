"""Room in a container: an object's outline, cells open from above, a second bowl's place.

Judged by raw PyBullet: the shapes' own sizes (``getCollisionShapeData``), the bodies'
closest points and the drawer link's bounds.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator

import pybullet
import pytest

from robocram.costmaps import CostmapLocations
from robocram.costmaps.distance_costs import AT_DISTANCE
from robocram.designators import a
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.scenes.environment_scene import EnvironmentScene
from robocram.tf import Pose
from robocram.world import World
from robocram.world.footprint import FOOTPRINT_SLACK, bounds_radius, footprint_radius

DRAWER = "drawer_unit_drawer_3"  # holds bowl-1 and bowl-2 side by side


@pytest.fixture(scope="module")
def kitchen() -> Iterator[EnvironmentScene]:
    scene = breakfast_scene("pr2")
    yield scene
    scene.world.close()


def _body(world: World, name: str) -> int:
    return world.object(name).body_id


def test_a_cylinder_needs_its_radius_and_a_box_its_half_diagonal(
    kitchen: EnvironmentScene,
) -> None:
    world = kitchen.world
    cup = pybullet.getCollisionShapeData(
        _body(world, "cup-1"), -1, physicsClientId=world.physics.client()
    )
    radius = cup[0][3][1]  # a cylinder's (length, radius, ...)
    assert footprint_radius(world, world.object("cup-1")) == pytest.approx(
        radius, abs=FOOTPRINT_SLACK + 0.001
    )
    spoon = pybullet.getCollisionShapeData(
        _body(world, "spoon-1"), -1, physicsClientId=world.physics.client()
    )
    sx, sy, _ = spoon[0][3]
    assert footprint_radius(world, world.object("spoon-1")) == pytest.approx(
        math.hypot(sx, sy) / 2, abs=0.002
    )


def test_a_round_bowl_needs_less_than_its_bounds_say(kitchen: EnvironmentScene) -> None:
    world = kitchen.world
    bowl = world.object("bowl-1")
    low, high = pybullet.getAABB(bowl.body_id, physicsClientId=world.physics.client())
    rim = (high[0] - low[0]) / 2  # the bowl is round: its bounds' half width is its rim
    assert footprint_radius(world, bowl) == pytest.approx(rim, abs=0.004)
    assert bounds_radius(world, bowl) == pytest.approx(rim * math.sqrt(2), abs=0.002)


def test_a_second_bowl_fits_beside_the_first_as_near_the_wall_as_the_margin_allows(
    kitchen: EnvironmentScene,
) -> None:
    world = kitchen.world
    joint = f"{DRAWER}_joint"
    world.set_joint_states("kitchen", {joint: 0.4})
    away = world.pose("bowl-2")
    world.set_pose("bowl-2", Pose((3.0, 3.0, 0.5)))  # out of the drawer
    try:
        locations = CostmapLocations(world, resolution=0.01)
        # 2 cm nearer the wall than where it is kept: the rim 4 cm off the wall (margin 3 cm)
        kept = world.link_pose("kitchen", DRAWER) * Pose((-0.26, -0.14, 0.0))
        wanted = a.location(in_=("kitchen", DRAWER), for_="bowl-2", at=kept.position, size=0.3)
        poses = list(itertools.islice(locations.poses(wanted), 5))
        assert poses
        kitchen_id = _body(world, "kitchen")
        drawer = world.object("kitchen").link_index[DRAWER]
        low, high = pybullet.getAABB(kitchen_id, drawer, physicsClientId=world.physics.client())
        for pose in poses:
            world.set_pose("bowl-2", pose)
            x, y, _ = pose.position
            assert low[0] < x < high[0] and low[1] < y < high[1]
            assert math.dist((x, y), kept.position[:2]) <= AT_DISTANCE + 0.005
            near = pybullet.getClosestPoints(
                _body(world, "bowl-2"), _body(world, "bowl-1"), 0.01,
                physicsClientId=world.physics.client(),
            )  # fmt: skip
            assert not near  # at least 1 cm from the first bowl
    finally:
        world.set_pose("bowl-2", away)
        world.set_joint_states("kitchen", {joint: 0.0})

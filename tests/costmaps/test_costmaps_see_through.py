"""The ``on`` location's ``see_through``: a spot under a body the asker looks past is free.

A robot standing at a table holding a second thing has its arm over the table; choosing
a spot there it must not take its own arm for an obstacle. Here a bowl hangs over the
spot in its place. Judged by raw PyBullet: a ray cast straight down over the spot found
meets the hanging bowl first, and the cup put there touches nothing but the table.
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
from robocram.designators.errors import DesignatorError
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose
from robocram.world import World

SPOT = (0.0, -1.3, 0.75)  # [m] map, on the kitchen table's top
OVER = 0.2  # [m] the bowl hangs this far over the table's top


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    scene = breakfast_scene("pr2")
    world = scene.world
    world.set_pose("bowl-2", Pose((SPOT[0], SPOT[1], SPOT[2] + OVER)))
    world.set_pose("cup-1", Pose((3.0, 3.0, 0.5)))  # off its drawer, out of every way
    yield world
    world.close()


def _wanted(**keys: object) -> object:
    return a.location(
        on=("kitchen", "table_top"), for_="cup-1", at=SPOT, size=0.3, resolution=0.01, **keys
    )


def _poses(world: World, wanted: object) -> list[Pose]:
    try:
        return list(itertools.islice(CostmapLocations(world).poses(wanted), 3))
    except DesignatorError:
        return []


def test_a_body_over_the_spot_takes_it(world: World) -> None:
    assert _poses(world, _wanted()) == []


def test_looking_past_the_body_finds_the_spot_under_it(world: World) -> None:
    poses = _poses(world, _wanted(see_through=("bowl-2",)))
    assert poses
    client = world.physics.client()
    bowl, cup = world.object("bowl-2").body_id, world.object("cup-1").body_id
    kitchen = world.object("kitchen").body_id
    away = world.pose("cup-1")
    for pose in poses:
        x, y, _ = pose.position
        assert math.dist((x, y), SPOT[:2]) <= AT_DISTANCE + 0.005
        hit = pybullet.rayTest((x, y, 2.0), (x, y, 0.0), physicsClientId=client)[0]
        assert hit[0] == bowl  # the spot lies under the bowl
        world.set_pose("cup-1", pose)
        try:
            touching = {
                other
                for other in (bowl, kitchen)
                if pybullet.getClosestPoints(cup, other, 0.005, physicsClientId=client)
            }
            assert touching == {kitchen}  # stands on the table, under the bowl, not in it
            low, _ = pybullet.getAABB(cup, physicsClientId=client)
            assert low[2] == pytest.approx(SPOT[2], abs=0.01)
        finally:
            world.set_pose("cup-1", away)

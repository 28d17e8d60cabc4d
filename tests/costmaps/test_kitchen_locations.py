"""Locations in the kitchen: in a drawer, on a counter part, and where to stand in the room."""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator

import pytest

from robocram.costmaps import CostmapLocations, LocationNotFound
from robocram.designators import a
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose

DRAWER = ("kitchen", "drawer_unit_drawer_3")


@pytest.fixture(scope="module")
def kitchen() -> Iterator[KitchenScene]:
    scene = kitchen_scene("pr2")
    yield scene
    scene.world.close()


def test_a_cup_put_in_the_drawer_rests_inside_it(kitchen: KitchenScene) -> None:
    world = kitchen.world
    locations = CostmapLocations(world, resolution=0.02)
    low, high = world.contacts.link_aabb(*DRAWER)
    poses = list(itertools.islice(locations.poses(a.location(in_=DRAWER, for_="cup-1")), 5))
    bowl = world.pose("bowl-1").position
    for pose in poses:
        x, y, z = pose.position
        assert low[0] < x < high[0] and low[1] < y < high[1]
        assert low[2] < z < high[2] - 0.02  # below the rim
        assert (x - bowl[0]) ** 2 + (y - bowl[1]) ** 2 > 0.1**2  # beside the bowl
    with world.snapshots.stored_state():
        world.set_pose("cup-1", poses[0])
        world.physics.simulate(1.0)
        assert world.pose("cup-1").distance_to(poses[0]) < 0.01
        assert world.contacts.contact("cup-1", "kitchen")


def test_standing_places_in_the_room_avoid_the_walls(kitchen: KitchenScene) -> None:
    world = kitchen.world
    locations = CostmapLocations(world)
    walls = [
        world.contacts.link_aabb("kitchen", f"wall_{side}")
        for side in ("north", "south", "east", "west")
    ]
    walls_low = [min(w[0][i] for w in walls) for i in range(2)]  # the room's outer bounds
    walls_high = [max(w[1][i] for w in walls) for i in range(2)]
    for key in ("visible_for", "reachable_for"):
        designator = a.location(**{key: "pr2"}, object="mug-1")
        for pose in itertools.islice(locations.poses(designator), 3):
            x, y, _ = pose.position
            assert walls_low[0] + 0.5 < x < walls_high[0] - 0.5, (key, pose)
            assert walls_low[1] + 0.5 < y < walls_high[1] - 0.5, (key, pose)


def test_thirty_rejections_in_a_row_name_the_validators(kitchen: KitchenScene) -> None:
    world = kitchen.world
    world.kb.consult("location_validator(near, never).", group="test_never")
    locations = CostmapLocations(world)
    locations.add_validator("never", lambda query, pose: False)
    designator = a.location(near="mug-1")
    with pytest.raises(LocationNotFound) as caught:
        list(locations.poses(designator))
    assert caught.value.rejections == {"never": 30}
    assert caught.value.designator is designator
    assert "never rejected 30" in str(caught.value)
    world.kb.consult("", group="test_never")


def test_an_object_shut_in_a_box_is_visible_from_nowhere(kitchen: KitchenScene) -> None:
    world = kitchen.world
    x, y, z = world.pose("milk-1").position
    with world.snapshots.stored_state():
        world.add_box("lid", (0.3, 0.3, 0.02), Pose((x, y, z + 0.25)))
        for dx, dy in ((0.16, 0), (-0.16, 0), (0, 0.16), (0, -0.16)):
            world.add_box(f"wall{dx}{dy}", (0.02 + abs(dy) * 2, 0.02 + abs(dx) * 2, 0.25),
                          Pose((x + dx, y + dy, z + 0.125)))  # fmt: skip
        with pytest.raises(LocationNotFound) as caught:
            next(CostmapLocations(world).poses(a.location(visible_for="pr2", object="milk-1")))
    assert caught.value.accepted == 0


def test_near_a_part_weighs_cells_by_the_parts_bounds(kitchen: KitchenScene) -> None:
    """``near`` takes a part, ``(object, link)``, as ``on`` does: the search looks into an
    opened drawer from stands near the drawer, not near the whole kitchen (whose bounds
    cover the room, so every cell in it was equally near)."""
    world = kitchen.world
    locations = CostmapLocations(world)
    low, high = world.contacts.link_aabb(*DRAWER)
    poses = list(itertools.islice(locations.poses(a.location(near=DRAWER)), 10))
    assert len(poses) == 10
    for pose in poses:
        x, y, _ = pose.position
        gap = math.hypot(max(low[0] - x, x - high[0], 0.0), max(low[1] - y, y - high[1], 0.0))
        assert gap < 1.0, pose  # beyond 1 m of the drawer's bounds nothing is near it

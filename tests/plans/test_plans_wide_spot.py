"""A bowl turned off the map's axes finds its table spot in the wider square (session 25,
Boxy's household seeds 7 and 9: bowl-1 held 16 degrees turned had no cell in the 0.3 m
square), the spot judged by raw PyBullet (the table's top under it); one arm and two try
the wide square alike, and only where the first had no cell."""

from __future__ import annotations

import math
from typing import Any

import pybullet
import pytest

from robocram.costmaps.errors import LocationNotFound
from robocram.designators.errors import GroundingError
from robocram.plans import table_trips
from robocram.plans.errors import DeliveryExhausted
from robocram.plans.location_poses import location_poses
from robocram.plans.table_arrangement import (
    SHARED,
    STANDARD_SETTING,
    Spot,
    Table,
    spots,
    table_with_seats,
)
from robocram.plans.table_trips import (
    SPOT_AREA,
    WIDE_SPOT_AREA,
    TableSetting,
    deliver_to_spot,
    spot_location,
)
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


def _tries(monkeypatch: pytest.MonkeyPatch, no_cell_in: set[float]) -> list[tuple[float, bool]]:
    """The squares and stand kinds one-armed delivery tries, each failing (no cell in the
    sizes ``no_cell_in``, a failed stand elsewhere) until the wide square from reach stands."""
    tried: list[tuple[float, bool]] = []

    def deliver(_held: Any, where: Any, _arm: str, *, log: Any, reach_stands: bool) -> None:
        size = where.get("size")
        tried.append((size, reach_stands))
        if size in no_cell_in:
            raise DeliveryExhausted("no cell", causes=(GroundingError("no cell"),))
        if not (size == WIDE_SPOT_AREA and reach_stands):
            raise DeliveryExhausted("no stand", causes=(RuntimeError("stand"),))

    monkeypatch.setattr(table_trips, "deliver", deliver)
    table = Table("kitchen", "table_top")
    bowl = Spot("bowl", 1, Pose((0.0, 1.0, 0.75)))
    held = type("Held", (), {"object_name": "bowl-1", "arm": "left"})()
    deliver_to_spot(held, bowl, TableSetting(table))
    return tried


def test_one_arm_tries_the_wide_square_only_where_the_first_had_no_cell(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    assert _tries(monkeypatch, {SPOT_AREA}) == [
        (SPOT_AREA, False),
        (WIDE_SPOT_AREA, False),
        (SPOT_AREA, True),
        (WIDE_SPOT_AREA, True),
    ]
    with pytest.raises(DeliveryExhausted):  # a failed stand: the square was not the cause
        _tries(monkeypatch, set())

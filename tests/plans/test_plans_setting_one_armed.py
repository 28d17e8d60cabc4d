"""One-armed table setting (``two_arms=False``): the PR2 brings one thing per trip.

The default, two-armed setting is judged in ``test_plans_activities.py``; this is the
way it was before, kept as an option. Judged by raw PyBullet queries: where each body is,
how far it is tilted, where its bottom is. The trips come from the plan's result.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

import pybullet
import pytest

from robocram.designators import an
from robocram.plans import perform
from robocram.plans.setting_table import TableSetting
from robocram.plans.table_arrangement import TOLERANCE
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene

UPRIGHT = 0.05  # [rad] how far a thing may lean and still stand
TABLE_TOP = 0.75  # [m] the kitchen table's top (tools/make_kitchen_urdf.py)


@dataclass
class Set:
    setting: TableSetting
    at: dict[str, tuple[tuple[float, float, float], float, float]]  # where, tilt, bottom


@pytest.fixture(scope="module")
def one_armed() -> Iterator[Set]:
    scene = breakfast_scene("pr2")
    world = scene.world
    client = world.physics.client()
    with simulated_robot(world, scene.robot):
        setting = perform(an.action(type="setting-table", people=2, two_arms=False))
    at = {}
    for name in scene.items:
        body = world.object(name).body_id
        position, orientation = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
        up = pybullet.getMatrixFromQuaternion(orientation)[8]
        low, _ = pybullet.getAABB(body, physicsClientId=client)
        at[name] = (
            (position[0], position[1], position[2]),
            math.acos(max(-1.0, min(1.0, up))),
            low[2],
        )
    yield Set(setting, at)
    world.close()


def test_every_thing_stands_at_its_seat(one_armed: Set) -> None:
    placed = one_armed.setting.placed
    assert sorted(s.type for s in placed.values()) == [
        "bowl", "bowl", "cup", "cup", "milk", "spoon", "spoon"
    ]  # fmt: skip
    for name, spot in placed.items():
        (x, y, _), tilt, bottom = one_armed.at[name]
        assert math.hypot(x - spot.pose.position[0], y - spot.pose.position[1]) <= TOLERANCE, name
        assert tilt <= UPRIGHT, name
        assert bottom == pytest.approx(TABLE_TOP, abs=0.01), name


def test_nothing_fell(one_armed: Set) -> None:
    for name, ((_, _, z), tilt, _) in one_armed.at.items():
        assert z > 0.4, name  # on a counter, shelf, drawer or the table; never the floor
        assert tilt <= UPRIGHT, name


def test_each_trip_carries_one_thing(one_armed: Set) -> None:
    trips = one_armed.setting.trips
    assert sorted(n for trip in trips for n in trip) == sorted(one_armed.setting.placed)
    assert all(len(trip) == 1 for trip in trips)

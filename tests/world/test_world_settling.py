"""Simulating with only some objects moving: the rest sleeps until touched, then wakes."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.tf import Pose
from robocram.world import World


@pytest.fixture
def world() -> Iterator[World]:
    w = World()
    w.add_floor()
    w.add_box("resting", (0.1, 0.1, 0.1), Pose((0.0, 0.0, 0.05)), mass=0.1)
    w.add_box("far", (0.1, 0.1, 0.1), Pose((1.0, 0.0, 0.05)), mass=1.0)
    w.add_box("dropped", (0.1, 0.1, 0.1), Pose((0.08, 0.0, 0.3)), mass=1.0)  # on its edge
    yield w
    w.close()


def test_the_moving_object_moves_as_among_awake_bodies(world: World) -> None:
    awake = world.copy()
    try:
        world.set_pose("dropped", Pose((0.5, 0.0, 0.2)))  # it touches nothing asleep
        awake.set_pose("dropped", Pose((0.5, 0.0, 0.2)))
        assert world.simulate(0.3, moving=("dropped",)) == awake.simulate(0.3)
        assert world.pose("dropped") == awake.pose("dropped")
        assert world.pose("far").distance_to(Pose((1.0, 0.0, 0.05))) < 1e-3
    finally:
        awake.close()


def test_a_sleeping_body_wakes_when_touched(world: World) -> None:
    awake = world.copy()
    try:
        world.simulate(0.5, moving=("dropped",))
        awake.simulate(0.5)
        for name in ("resting", "dropped"):
            assert world.pose(name).distance_to(awake.pose(name)) < 1e-3
        assert world.pose("resting").distance_to(Pose((0.0, 0.0, 0.05))) > 0.01  # pushed
    finally:
        awake.close()


def test_the_bodies_are_awake_afterwards(world: World) -> None:
    world.simulate(0.05, moving=("dropped",))
    world.set_pose("far", Pose((1.0, 0.0, 0.5)))
    world.simulate(0.1)
    assert world.pose("far").position[2] < 0.45  # it falls again

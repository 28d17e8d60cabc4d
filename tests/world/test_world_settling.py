"""Settling an object: the rest sleeps until touched, and is as awake as before afterwards."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.tf import Pose
from robocram.world import World
from robocram.world.settling import at_rest


@pytest.fixture
def world() -> Iterator[World]:
    w = World()
    w.bodies.add_floor()
    w.add_box("resting", (0.1, 0.1, 0.1), Pose((0.0, 0.0, 0.05)), mass=0.1)
    w.add_box("far", (0.1, 0.1, 0.1), Pose((1.0, 0.0, 0.05)), mass=1.0)
    w.add_box("dropped", (0.1, 0.1, 0.1), Pose((0.08, 0.0, 0.3)), mass=1.0)  # on its edge
    yield w
    w.close()


def test_the_object_moves_as_among_awake_bodies_until_it_rests(world: World) -> None:
    awake = world.copy()
    try:
        for w in (world, awake):
            w.set_pose("dropped", Pose((0.5, 0.0, 0.055)))  # 5 mm above the floor
        steps = world.physics.settle("dropped", 1.0)
        assert 4 < steps < 60  # it landed and rested well before the second was up
        awake.physics.simulate(steps * world.time_step)
        assert world.pose("dropped") == awake.pose("dropped")
        assert world.pose("far").distance_to(Pose((1.0, 0.0, 0.05))) < 1e-3
        before = world.pose("dropped")
        world.physics.simulate(2 * world.time_step)
        assert at_rest(before, world.pose("dropped"))
    finally:
        awake.close()


def test_a_sleeping_body_wakes_when_touched(world: World) -> None:
    awake = world.copy()
    try:
        steps = world.physics.settle("dropped", 0.5)
        awake.physics.simulate(steps * world.time_step)
        for name in ("resting", "dropped"):
            assert world.pose(name).distance_to(awake.pose(name)) < 1e-3
        assert world.pose("resting").distance_to(Pose((0.0, 0.0, 0.05))) > 0.01  # pushed
    finally:
        awake.close()


def test_the_bodies_are_awake_afterwards(world: World) -> None:
    world.add_box("hanging", (0.1, 0.1, 0.1), Pose((2.0, 0.0, 0.5)), mass=1.0)
    world.physics.settle("dropped", 0.05)
    z = world.pose("hanging").position[2]
    assert z > 0.499  # asleep in the air: it fell only before the first step's end
    world.physics.simulate(world.time_step)
    assert world.pose("hanging").position[2] < z  # it falls in the very next step


def test_no_time_no_step(world: World) -> None:
    assert world.physics.settle("dropped", 0.0) == 0
    assert world.pose("dropped") == Pose((0.08, 0.0, 0.3))


def test_a_stop_leaves_the_bodies_awake(world: World) -> None:
    world.add_box("hanging", (0.1, 0.1, 0.1), Pose((2.0, 0.0, 0.5)), mass=1.0)
    looks: list[int] = []

    def stop() -> None:
        looks.append(1)
        if len(looks) > 4:
            raise RuntimeError("stopped")

    with pytest.raises(RuntimeError, match="stopped"):
        world.physics.settle("dropped", 1.0, stop_check=stop)
    z = world.pose("hanging").position[2]
    world.physics.simulate(world.time_step)
    assert world.pose("hanging").position[2] < z

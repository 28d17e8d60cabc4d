"""A snapshot puts each base back to the bit: PyBullet reads a base through a rotation
matrix, a last bit off what was written, so a snapshot writes again the inputs the world
last wrote (read back raw from PyBullet here, not through the world)."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pybullet
import pytest

from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.world import Camera, World

# A stand of the HSR's kitchen mug transport: PyBullet reads its yaw a last bit off.
STAND = Pose(
    (-1.524999976158142, 1.6048165564239025, 0.0),
    (0.0, 0.0, 0.4512218261512583, 0.8924118239942385),
)


@pytest.fixture(scope="module")
def kitchen() -> Iterator[World]:
    world = kitchen_scene("hsrb").world
    yield world
    world.close()


def _raw(world: World, name: str) -> tuple[tuple[float, ...], tuple[float, ...]]:
    body = world.object(name).body_id
    pos, orn = pybullet.getBasePositionAndOrientation(body, physicsClientId=world.physics.client())
    return tuple(pos), tuple(orn)


def test_a_snapshot_puts_a_written_base_back_to_the_bit(kitchen: World) -> None:
    kitchen.set_pose("hsrb", STAND)
    before = _raw(kitchen, "hsrb")
    pos, orn = before
    pybullet.resetBasePositionAndOrientation(
        kitchen.object("hsrb").body_id, pos, orn, physicsClientId=kitchen.physics.client()
    )
    assert _raw(kitchen, "hsrb") != before  # the premise: writing the read moves it a bit
    kitchen.set_pose("hsrb", STAND)
    assert _raw(kitchen, "hsrb") == before
    for _ in range(3):  # restored again and again, it stays
        with kitchen.snapshots.stored_state():
            kitchen.set_pose("hsrb", Pose((1.0, 0.5, 0.0)))
            assert _raw(kitchen, "hsrb") != before
        assert _raw(kitchen, "hsrb") == before
    state = kitchen.snapshots.capture()
    kitchen.set_pose("hsrb", Pose((0.0, 0.0, 0.0)))
    kitchen.snapshots.restore(state)
    kitchen.snapshots.restore(state)
    assert _raw(kitchen, "hsrb") == before


def test_a_visibility_check_leaves_the_body_it_isolates_to_the_bit(kitchen: World) -> None:
    kitchen.set_pose("hsrb", STAND)
    before = _raw(kitchen, "hsrb")
    look = Pose.from_xyz_rpy((0.0, 1.6, 1.0), (-math.pi / 2, 0.0, -math.pi / 2))  # along +x
    for method in ("ray", "render"):
        kitchen.view.visibility_from(Camera(look, 1.0, 0.8), "hsrb", method)
        assert _raw(kitchen, "hsrb") == before, method


def _settled(world: World, yaw: float) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The mug's base as PyBullet reads it after physics settled it from ``yaw``."""
    x, y, z = world.pose("mug-1").position
    world.set_pose("mug-1", Pose.from_xyz_rpy((x, y, z + 0.002), (0.0, 0.0, yaw)))
    world.physics.simulate(0.1)  # physics moved it: what would put it here is unknown
    return _raw(world, "mug-1")


def _moves_when_written_back(world: World, yaw: float) -> bool:
    read = _settled(world, yaw)
    pybullet.resetBasePositionAndOrientation(
        world.object("mug-1").body_id, *read, physicsClientId=world.physics.client()
    )
    return _raw(world, "mug-1") != read


def test_a_snapshot_leaves_a_body_physics_moved_as_it_stands_when_the_block_left_it(
    kitchen: World,
) -> None:
    yaw = next(y for y in (0.1 * k for k in range(1, 60)) if _moves_when_written_back(kitchen, y))
    before = _settled(kitchen, yaw)
    with kitchen.snapshots.stored_state():
        kitchen.set_pose("hsrb", Pose((1.0, 0.5, 0.0)))
    assert _raw(kitchen, "mug-1") == before

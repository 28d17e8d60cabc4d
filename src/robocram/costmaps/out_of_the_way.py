"""Moving bodies out of the way of ray casts for a moment, and back exactly."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from contextlib import contextmanager

from robocram.tf import Pose
from robocram.world import World, WorldObject

AWAY = 1000.0  # [m] how far up the bodies wait
APART = 10.0  # [m] sideways between them, so they do not touch each other up there


@contextmanager
def out_of_the_way(world: World, bodies: Sequence[WorldObject | None]) -> Iterator[None]:
    """Lift ``bodies`` (None entries skipped) far up for the block; restore their poses."""
    moved = [b for b in bodies if b is not None]
    before = [world.pose(b) for b in moved]
    try:
        for index, (body, pose) in enumerate(zip(moved, before, strict=True)):
            x, y, z = pose.position
            world.set_pose(body, Pose((x + APART * (index + 1), y, z + AWAY), pose.orientation))
        yield
    finally:
        for body, pose in zip(moved, before, strict=True):
            world.set_pose(body, pose)

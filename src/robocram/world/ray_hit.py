"""The first body a ray hits."""

from __future__ import annotations

from dataclasses import dataclass

from robocram.tf import Vector3
from robocram.world.world_object import WorldObject


@dataclass(frozen=True)
class RayHit:
    """Where a ray first met ``obj`` (its ``link`` name, or None for the base)."""

    obj: WorldObject
    link: str | None
    position: Vector3  # [m] in the world
    normal: Vector3
    distance: float  # [m] from the ray's start

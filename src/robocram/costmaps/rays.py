"""Ray batches of any length (pybullet takes at most 16384 rays per call)."""

from __future__ import annotations

from collections.abc import Sequence

from robocram.tf import Vector3
from robocram.world import RayHit, World

BATCH = 16000


def cast_rays(
    world: World, starts: Sequence[Vector3], ends: Sequence[Vector3]
) -> list[RayHit | None]:
    """``world.view.ray_cast_batch`` in chunks pybullet accepts."""
    hits: list[RayHit | None] = []
    for i in range(0, len(starts), BATCH):
        hits.extend(world.view.ray_cast_batch(starts[i : i + BATCH], ends[i : i + BATCH]))
    return hits

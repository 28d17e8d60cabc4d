"""The first body a ray hits, for one ray or a batch."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import pybullet

from robocram.tf import Vector3
from robocram.world.world_core import WorldCore
from robocram.world.world_object import WorldObject


@dataclass(frozen=True)
class RayHit:
    """Where a ray first met ``obj`` (its ``link`` name, or None for the base)."""

    obj: WorldObject
    link: str | None
    position: Vector3  # [m] in the world
    normal: Vector3
    distance: float  # [m] from the ray's start


def cast_rays(
    world: WorldCore, starts: Sequence[Vector3], ends: Sequence[Vector3]
) -> list[RayHit | None]:
    """The first hit of each segment ``starts[i]``..``ends[i]`` [m], in one pybullet call."""
    by_body = {o.body_id: o for o in world.objects()}
    hits = pybullet.rayTestBatch(
        [list(s) for s in starts], [list(e) for e in ends], physicsClientId=world.physics_client()
    )
    out: list[RayHit | None] = []
    for start, end, hit in zip(starts, ends, hits, strict=True):
        obj = by_body.get(hit[0])
        if obj is None:
            out.append(None)
            continue
        link = next((n for n, i in obj.link_index.items() if i == hit[1]), None)
        length = math.dist(end, start)
        out.append(RayHit(obj, link, tuple(hit[3]), tuple(hit[4]), hit[2] * length))
    return out

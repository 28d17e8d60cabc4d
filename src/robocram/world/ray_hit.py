"""The first body a ray hits, for one ray or a batch."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.tf import Vector3
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_object import PART_STRIDE, WorldObject

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade

RAY_BATCH = 16000  # pybullet takes at most 16384 rays per call


@dataclass(frozen=True)
class RayHit:
    """Where a ray first met ``obj`` (its ``link`` name, or None for the base)."""

    obj: WorldObject
    link: str | None
    position: Vector3  # [m] in the world
    normal: Vector3
    distance: float  # [m] from the ray's start


def cast_rays(
    world: WorldFacade, starts: Sequence[Vector3], ends: Sequence[Vector3]
) -> list[RayHit | None]:
    """The first hit of each segment ``starts[i]``..``ends[i]`` [m], in one pybullet call."""
    hits = pybullet.rayTestBatch(
        [list(s) for s in starts], [list(e) for e in ends], physicsClientId=world.physics.client()
    )
    links: dict[int, dict[int, str]] = {}  # body -> link slot -> name, built on first hit
    out: list[RayHit | None] = []
    for start, end, hit in zip(starts, ends, hits, strict=True):
        obj = world.bodies.owner(hit[0])
        if obj is None:
            out.append(None)
            continue
        names = links.get(obj.body_id)
        if names is None:
            names = links[obj.body_id] = _link_names(obj)
        length = math.dist(end, start)
        link = names.get(obj.slot(hit[0], hit[1]))
        out.append(RayHit(obj, link, tuple(hit[3]), tuple(hit[4]), hit[2] * length))
    return out


def _link_names(obj: WorldObject) -> dict[int, str]:
    """Link index -> name; the first name of an index wins (extra frames share their host's)."""
    names: dict[int, str] = {}
    for name, index in obj.link_index.items():
        names.setdefault(index, name)
    return names


def first_hit_bodies(
    world: WorldFacade, starts: NDArray[np.float64], ends: NDArray[np.float64]
) -> NDArray[np.int64]:
    """Body id (-1 for none) of the first hit of each segment (N x 3 arrays [m]).

    The cheap form of :func:`cast_rays` for many rays that only ask "anything there?".
    """
    cid = world.physics.client()
    out = np.full(len(starts), -1, dtype=np.int64)
    for i in range(0, len(starts), RAY_BATCH):
        hits = pybullet.rayTestBatch(  # arrays go in as they are: 4x faster than lists
            np.ascontiguousarray(starts[i : i + RAY_BATCH], dtype=np.float64),
            np.ascontiguousarray(ends[i : i + RAY_BATCH], dtype=np.float64),
            physicsClientId=cid,
        )
        out[i : i + len(hits)] = [h[0] for h in hits]
    return main_bodies(world, out)


def main_bodies(world: WorldFacade, bodies: NDArray[np.int64]) -> NDArray[np.int64]:
    """``bodies`` (ids, -1 for none) with each part of an object cut in parts (see
    :class:`~robocram.world.world_object.WorldObject`) read as its object's ``body_id``."""
    split = [o for o in world.objects() if o.parts]
    if not split:
        return bodies
    out = bodies.copy()
    for obj in split:
        out[np.isin(bodies, obj.parts)] = obj.body_id
    return out


@dataclass(frozen=True)
class RayHits:
    """The first hit of each of N rays as arrays: the cheap form of :func:`cast_rays` for
    the thousands of rays a costmap casts (no object per ray)."""

    bodies: NDArray[np.int64]  # (N,) body id, -1 where nothing is hit
    links: NDArray[np.int64]  # (N,) link index (-1: the base)
    positions: NDArray[np.float64]  # (N, 3) [m]
    normals: NDArray[np.float64]  # (N, 3)


def ray_hits(world: WorldFacade, starts: NDArray[np.float64], ends: NDArray[np.float64]) -> RayHits:
    """First hits of the segments ``starts[i]``..``ends[i]`` (N x 3 arrays [m])."""
    cid = world.physics.client()
    rows: list[tuple[object, ...]] = []
    for i in range(0, len(starts), RAY_BATCH):
        rows += pybullet.rayTestBatch(
            np.ascontiguousarray(starts[i : i + RAY_BATCH], dtype=np.float64),
            np.ascontiguousarray(ends[i : i + RAY_BATCH], dtype=np.float64),
            physicsClientId=cid,
        )
    count = len(rows)
    columns = list(zip(*rows, strict=True)) if rows else [(), (), (), (), ()]
    bodies = np.array(columns[0], dtype=np.int64).reshape(count)
    links = np.array(columns[1], dtype=np.int64).reshape(count)
    for obj in world.objects():
        for part, body in enumerate(obj.parts[1:], start=1):
            links[bodies == body] += part * PART_STRIDE
    return RayHits(
        main_bodies(world, bodies),
        links,
        np.array(columns[3], dtype=np.float64).reshape(count, 3),
        np.array(columns[4], dtype=np.float64).reshape(count, 3),
    )


PAST_STEP = 0.005  # [m] a ray that met a body seen through goes on this far beyond the hit
PAST_ROUNDS = 12  # bodies seen through one after another along a ray, at most


def ray_hits_past(
    world: WorldFacade,
    starts: NDArray[np.float64],
    ends: NDArray[np.float64],
    past: NDArray[np.int64],
) -> RayHits:
    """First hits of the segments, looking past the bodies ``past`` (ids).

    A ray that meets one of them goes on from :data:`PAST_STEP` beyond the hit, as a
    person looking for a free spot on a table looks past their own arm. A ray still on
    such a body after :data:`PAST_ROUNDS` rounds reports that body.
    """
    hits = ray_hits(world, starts, ends)
    bodies, links = hits.bodies.copy(), hits.links.copy()
    positions, normals = hits.positions.copy(), hits.normals.copy()
    length = np.linalg.norm(ends - starts, axis=1)
    along = (ends - starts) / np.where(length > 0.0, length, 1.0)[:, None]
    for _ in range(PAST_ROUNDS):
        again = np.flatnonzero(np.isin(bodies, past))
        if again.size == 0:
            break
        beyond = positions[again] + along[again] * PAST_STEP
        left = np.einsum("ij,ij->i", ends[again] - beyond, along[again]) > 0.0
        again, beyond = again[left], beyond[left]
        if again.size == 0:
            break
        more = ray_hits(world, beyond, ends[again])
        bodies[again], links[again] = more.bodies, more.links
        positions[again], normals[again] = more.positions, more.normals
    return RayHits(bodies, links, positions, normals)

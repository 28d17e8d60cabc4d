"""How much of an object a camera sees, by batched ray casts or by a small render.

Both methods compare the object as the camera sees it in the scene with the object alone.
For rays, "alone" is computed from the object's collision shapes in numpy (Bullet's ray
tests against mesh parts are slow); for renders, and for shapes not modelled there, the
object and the camera are both shifted far up, out of everyone's way
(:data:`ISOLATION_OFFSET`), looked at, and put back exactly. The fraction counts parts
outside the field of view as unseen, so an object half out of the image is half visible.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.tf import Vector3
from robocram.world.camera import Camera
from robocram.world.pybullet_backend import pybullet
from robocram.world.ray_hit import first_hit_bodies, main_bodies
from robocram.world.shape_rays import lone_body
from robocram.world.world_object import WorldObject

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade

ISOLATION_OFFSET = (0.0, 0.0, 1000.0)  # [m] far above any scene, beyond every camera's far
SURFACE_GAP = 1e-3  # [m] scene rays stop this short of the object's surface


@dataclass(frozen=True)
class Visibility:
    """Seen share of an object and who hides the rest.

    ``samples`` counts the rays (or pixels) that hit the object when it is alone.
    """

    fraction: float
    occluders: tuple[str, ...]
    samples: int


def aabb(world: WorldFacade, obj: WorldObject) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """World axis-aligned bounds ``(lower, upper)`` [m] over all of ``obj``'s links."""
    cid = world.physics.client()
    boxes = []
    for body in obj.bodies:
        boxes.append(pybullet.getAABB(body, -1, physicsClientId=cid))
        for i in range(pybullet.getNumJoints(body, physicsClientId=cid)):
            boxes.append(pybullet.getAABB(body, i, physicsClientId=cid))
    lows = np.array([b[0] for b in boxes])
    highs = np.array([b[1] for b in boxes])
    return lows.min(axis=0), highs.max(axis=0)


def link_aabb(world: WorldFacade, obj: WorldObject, index: int) -> tuple[Vector3, Vector3]:
    """World axis-aligned bounds ``(lower, upper)`` [m] of link ``index`` of ``obj``."""
    low, high = pybullet.getAABB(*obj.locate(index), physicsClientId=world.physics.client())
    return (float(low[0]), float(low[1]), float(low[2])), (
        float(high[0]),
        float(high[1]),
        float(high[2]),
    )


@contextmanager
def isolated(world: WorldFacade, obj: WorldObject) -> Iterator[None]:
    """Shift ``obj`` by :data:`ISOLATION_OFFSET`; put it back exactly afterwards (with the
    bases it was written with: a base read from PyBullet and written back moves a bit)."""
    cid = world.physics.client()
    kept = world.snapshots.bases(obj)
    speeds = [pybullet.getBaseVelocity(body, physicsClientId=cid) for body, _, _ in kept]
    shifted = [
        (body, tuple(p + o for p, o in zip(pos, ISOLATION_OFFSET, strict=True)), orn)
        for body, pos, orn in kept
    ]
    world.snapshots.put_bases(obj, shifted)
    try:
        yield
    finally:
        world.snapshots.put_bases(obj, kept)
        for (body, _, _), (lin, ang) in zip(kept, speeds, strict=True):
            pybullet.resetBaseVelocity(body, lin, ang, physicsClientId=cid)


def _tangent_grid(
    world: WorldFacade, camera: Camera, obj: WorldObject, grid: int
) -> NDArray[np.float64] | None:
    """Image tangents ``(x/z, y/z)`` of a grid over the projection of ``obj``'s bounds."""
    low, high = aabb(world, obj)
    corners = np.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1])
                        for z in (low[2], high[2])])  # fmt: skip
    optical = camera.to_optical(corners)
    front = optical[optical[:, 2] > camera.near]
    if len(front) == 0:
        return None
    tangents = front[:, :2] / front[:, 2:3]
    lo, hi = tangents.min(axis=0), tangents.max(axis=0)
    steps = (np.arange(grid) + 0.5) / grid
    tx = lo[0] + steps * (hi[0] - lo[0])
    ty = lo[1] + steps * (hi[1] - lo[1])
    xs, ys = np.meshgrid(tx, ty)  # rows by y, x fastest
    return np.stack([xs.ravel(), ys.ravel()], axis=1)


def _first_hits(world: WorldFacade, camera: Camera, tangents: NDArray[np.float64]) -> list[int]:
    starts, ends = camera.ray_ends(tangents)
    hits = pybullet.rayTestBatch(starts, ends, physicsClientId=world.physics.client())
    bodies = np.array([int(h[0]) for h in hits], dtype=np.int64)
    return [int(b) for b in main_bodies(world, bodies)]


def ray_visibility(
    world: WorldFacade, camera: Camera, obj: WorldObject, grid: int = 24
) -> Visibility:
    """Visibility of ``obj`` from ``camera`` by ``grid`` x ``grid`` rays over its outline.

    Where each ray would meet the object alone comes from its collision shapes
    (:mod:`~robocram.world.shape_rays`); Bullet then casts only the rays that meet it and
    lie in view, each up to just short of the object (moved out of their way), so whatever
    such a ray hits hides that part of the object.
    """
    tangents = _tangent_grid(world, camera, obj, grid)
    if tangents is None:
        return Visibility(0.0, (), 0)
    lone = lone_body(world, obj)
    if lone is None:  # a shape we do not model: Bullet casts against the object alone
        return _bullet_ray_visibility(world, camera, obj, tangents)
    starts, ends = camera.ray_ends(tangents)
    length = np.linalg.norm(ends - starts, axis=1)
    dirs = (ends - starts) / length[:, None]
    depth = lone.first_hit(starts, dirs, length)
    on_object = np.isfinite(depth)
    total = int(np.count_nonzero(on_object))
    if total == 0:
        return Visibility(0.0, (), 0)
    look = on_object & _in_view(camera, tangents)
    short = np.maximum(depth[look] - SURFACE_GAP, 0.0)[:, None]
    with isolated(world, obj):
        scene = first_hit_bodies(world, starts[look], starts[look] + dirs[look] * short)
    seen = int(np.count_nonzero(scene < 0))
    return Visibility(seen / total, _names(world, set(scene[scene >= 0].tolist())), total)


def _in_view(camera: Camera, tangents: NDArray[np.float64]) -> NDArray[np.bool_]:
    th, tv = camera.tan_half
    return np.asarray((np.abs(tangents[:, 0]) <= th) & (np.abs(tangents[:, 1]) <= tv))


def _bullet_ray_visibility(
    world: WorldFacade, camera: Camera, obj: WorldObject, tangents: NDArray[np.float64]
) -> Visibility:
    """:func:`ray_visibility` with Bullet casting against the object alone too (slower)."""
    with isolated(world, obj):
        alone = _first_hits(world, camera.shifted(ISOLATION_OFFSET), tangents)
    on_object = tangents[np.array(alone) == obj.body_id]
    if len(on_object) == 0:
        return Visibility(0.0, (), 0)
    in_view = _in_view(camera, on_object)
    scene = np.array(_first_hits(world, camera, on_object))
    seen = int(np.count_nonzero((scene == obj.body_id) & in_view))
    blockers = set(scene[in_view & (scene != obj.body_id) & (scene >= 0)].tolist())
    return Visibility(seen / len(on_object), _names(world, blockers), len(on_object))


def segmentation(world: WorldFacade, camera: Camera, width: int, height: int) -> NDArray[np.int64]:
    """Per-pixel body ids (-1 for nothing) of a TINY-renderer image of ``camera``."""
    _, _, _, _, seg = pybullet.getCameraImage(
        width,
        height,
        camera.view_matrix(),
        camera.projection_matrix(),
        renderer=pybullet.ER_TINY_RENDERER,
        physicsClientId=world.physics.client(),
    )
    return main_bodies(world, np.reshape(np.asarray(seg, dtype=np.int64), (height, width)))


def render_visibility(
    world: WorldFacade, camera: Camera, obj: WorldObject, height: int = 120
) -> Visibility:
    """Visibility of ``obj`` from ``camera`` by comparing segmentation renders.

    The lone object is rendered at twice the image extent (same pixel size), so the part of
    it outside the camera's view is counted too; the centre of that image lines up
    pixel for pixel with the scene render.
    """
    width, height = camera.image_size(height + height % 2)
    width += width % 2
    camera = camera.with_aspect(width / height)
    scene = segmentation(world, camera, width, height)
    with isolated(world, obj):
        lone = camera.shifted(ISOLATION_OFFSET).widened(2.0)
        alone = segmentation(world, lone, 2 * width, 2 * height)
    total = int(np.count_nonzero(alone == obj.body_id))
    if total == 0:
        return Visibility(0.0, (), 0)
    rows, cols = height // 2, width // 2
    centre = alone[rows : rows + height, cols : cols + width] == obj.body_id
    seen = int(np.count_nonzero(scene == obj.body_id))
    blockers = set(scene[centre & (scene != obj.body_id) & (scene >= 0)].tolist())
    return Visibility(min(1.0, seen / total), _names(world, blockers), total)


def _names(world: WorldFacade, bodies: set[int]) -> tuple[str, ...]:
    by_body = {o.body_id: o.name for o in world.objects()}
    return tuple(sorted(by_body[b] for b in bodies if b in by_body))

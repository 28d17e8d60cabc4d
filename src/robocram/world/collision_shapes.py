"""The collision shapes of a world object, where they are now, as plain values.

Other engines (the motion layer's coal scene) take a snapshot of the world from these.
They are read from the body's recipe (its shape, mesh or URDF) and placed at the links'
current poses, not from PyBullet's shape data: PyBullet reports a link of several shapes
with its first shape missing and frames relative to the centre of mass.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Literal

from robocram.robots import RobotModel
from robocram.robots.urdf_elements import Geometry
from robocram.tf import Pose, Vector3
from robocram.world.body_spec import MeshSpec, ShapeSpec, UrdfSpec
from robocram.world.errors import WorldUsageError, WorldValueError
from robocram.world.world_object import RobotObject, WorldObject

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade

CollisionKind = Literal["box", "cylinder", "sphere", "mesh", "plane"]


@dataclass(frozen=True)
class CollisionShape:
    """One collision shape of ``obj``'s ``link`` at ``pose`` (in map).

    ``extents`` [m]: a box's full extents, a cylinder's (2 r, 2 r, length) along z, a
    sphere's (2 r, 2 r, 2 r); a mesh's scale; a plane (z = 0 of ``pose``) ignores them.
    """

    obj: str
    link: str  # the link's name; a single-shape body's is the object's name
    kind: CollisionKind
    extents: Vector3
    pose: Pose
    mesh: str = ""  # absolute path of a mesh file


def _scaled(geometry: Geometry, scale: float) -> tuple[CollisionKind, Vector3]:
    if geometry.kind == "mesh":
        sx, sy, sz = geometry.scale
        return "mesh", (sx * scale, sy * scale, sz * scale)
    extents = geometry.extents()
    if extents is None:  # pragma: no cover - every kind but mesh has extents
        raise WorldValueError(f"geometry {geometry!r} has no extents")
    return geometry.kind, (extents[0] * scale, extents[1] * scale, extents[2] * scale)


def _urdf_shapes(
    world: WorldFacade, obj: WorldObject, model: RobotModel, scale: float
) -> list[CollisionShape]:
    shapes: list[CollisionShape] = []
    for link in model.links.values():
        if not link.collisions:
            continue
        link_pose = world.link_pose(obj, link.name)
        for collision in link.collisions:
            kind, extents = _scaled(collision.geometry, scale)
            x, y, z = collision.origin.position
            origin = Pose((x * scale, y * scale, z * scale), collision.origin.orientation)
            shapes.append(
                CollisionShape(
                    obj.name, link.name, kind, extents, link_pose * origin,
                    collision.geometry.filename,
                )
            )  # fmt: skip
    return shapes


def collision_shapes(world: WorldFacade, obj: WorldObject) -> list[CollisionShape]:
    """Every collision shape of ``obj`` at its current pose, in its links' order."""
    spec = obj.spec
    if isinstance(obj, RobotObject):
        return _urdf_shapes(world, obj, obj.description.model, 1.0)
    if isinstance(spec, UrdfSpec):
        # the model the body was loaded from (a spec checked by its caller has none kept)
        model = obj.urdf_model or RobotModel.from_file(Path(spec.path).resolve())
        return _urdf_shapes(world, obj, model, spec.scale)
    pose = world.pose(obj)
    if isinstance(spec, MeshSpec):
        scale = (spec.scale,) * 3
        return [CollisionShape(obj.name, obj.name, "mesh", scale, pose, str(spec.path))]
    if isinstance(spec, ShapeSpec):
        return [CollisionShape(obj.name, obj.name, spec.shape, spec.size, pose)]
    raise WorldUsageError(
        f"object {obj.name!r} has an unknown body spec {spec!r}"
    )  # pragma: no cover

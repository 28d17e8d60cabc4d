"""What a world's bodies look like: one drawable part per visual shape, on a link.

Robots and URDF objects take their visuals from the URDF model; primitive and mesh bodies
from their body spec. The viewer places each part at ``map_T_link * link_T_part``.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from robocram.robots import Geometry, RobotModel
from robocram.tf import Pose
from robocram.world import MeshSpec, RobotObject, ShapeSpec, UrdfSpec, World, WorldObject

Rgba = tuple[float, float, float, float]
DEFAULT_COLOR: Rgba = (0.75, 0.75, 0.78, 1.0)
FLOOR_SIZE = 8.0  # [m] side of the square drawn for a plane
FLOOR_COLOR: Rgba = (0.82, 0.84, 0.86, 1.0)


@dataclass(frozen=True)
class VisualPart:
    """A shape drawn on ``link`` of ``body`` (``None``: the body's root) at ``origin``."""

    body: str
    link: str | None
    origin: Pose  # link_T_part
    geometry: Geometry
    color: Rgba


def visual_parts(world: World) -> list[VisualPart]:
    """Every drawable part of every body in ``world``."""
    parts: list[VisualPart] = []
    for obj in world.objects():
        parts.extend(_parts_of(obj))
    return parts


def _parts_of(obj: WorldObject) -> list[VisualPart]:
    spec = obj.spec
    if isinstance(obj, RobotObject) and obj.description.model is not None:
        return _model_parts(obj.name, obj.description.model)
    if isinstance(spec, UrdfSpec):
        return _model_parts(obj.name, RobotModel.from_file(spec.path))
    if isinstance(spec, ShapeSpec):
        return [VisualPart(obj.name, None, Pose(), _shape_geometry(spec), _shape_color(spec))]
    if isinstance(spec, MeshSpec):
        mesh = Geometry("mesh", filename=str(Path(spec.path).resolve()), scale=(spec.scale,) * 3)
        return [VisualPart(obj.name, None, Pose(), mesh, spec.color)]
    return []


def _model_parts(body: str, model: RobotModel) -> list[VisualPart]:
    return [
        VisualPart(body, link.name, visual.origin, visual.geometry, visual.rgba or DEFAULT_COLOR)
        for link in model.links.values()
        for visual in link.visuals
    ]


def _shape_geometry(spec: ShapeSpec) -> Geometry:
    sx, sy, sz = spec.size
    if spec.shape == "box":
        return Geometry("box", size=(sx, sy, sz))
    if spec.shape == "cylinder":
        return Geometry("cylinder", radius=sx / 2, length=sz)
    if spec.shape == "sphere":
        return Geometry("sphere", radius=sx / 2)
    return Geometry("box", size=(FLOOR_SIZE, FLOOR_SIZE, 0.001))


def _shape_color(spec: ShapeSpec) -> Rgba:
    return FLOOR_COLOR if spec.shape == "plane" else spec.color

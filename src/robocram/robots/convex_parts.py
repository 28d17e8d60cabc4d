"""A link whose mesh's convex hull overstates it collides as the mesh's convex parts.

PyBullet collides a mesh of a moving body as its convex hull, and so do the coal checks
(:mod:`robocram.motion.coal_shapes`). For most links that costs millimetres; Baxter's
torso is shaped like a C seen from the side, and its hull fills the gap in front, 0.24 m
of torso that is not there, just where its elbows swing reaching down to a table. A
description names such links in ``decomposed_links`` (the draft does where the hull
overreaches: :mod:`robocram.robots.draft.hull_overreach`); at load each named link's
mesh collisions become one OBJ file holding one object per convex part, which PyBullet
loads as a compound of hulls and coal reads part by part. Making the parts takes
PyBullet's V-HACD, which only ``robocram.world`` may call: this layer takes the maker as
a callable (:data:`PartsFile`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import replace
from pathlib import Path

from robocram.robots.errors import DescriptionCheckError, NameProblem
from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Collision, Geometry

# a mesh file and its scale -> an OBJ file of the scaled mesh's convex parts, one object each
PartsFile = Callable[[Path, tuple[float, float, float]], Path]


def with_convex_parts(model: RobotModel, links: Iterable[str], parts_file: PartsFile) -> RobotModel:
    """``model`` with each mesh collision of ``links`` replaced by its convex parts (the
    OBJ ``parts_file`` makes, at scale 1); ``model`` itself when ``links`` is empty.

    The result is kept with ``model`` (``RobotModel.derived``), so worlds loading one
    description share one model (and the motion layer's geometry built from it).

    Raises:
        DescriptionCheckError: a named link is not in the model or has no mesh collision.
    """
    key = tuple(sorted(set(links)))
    if not key:
        return model
    kept = model.derived(_decomposed_models)
    if key not in kept:
        kept[key] = _decomposed(model, key, parts_file)
    return kept[key]


def _decomposed_models(model: RobotModel) -> dict[tuple[str, ...], RobotModel]:
    """The decomposed models made from ``model``, by the links decomposed."""
    return {}


def _decomposed(model: RobotModel, names: tuple[str, ...], parts_file: PartsFile) -> RobotModel:
    problems = [
        NameProblem("link with a mesh collision", name, "decomposed_links", ())
        for name in names
        if name not in model.links
        or not any(c.geometry.kind == "mesh" for c in model.links[name].collisions)
    ]
    if problems:
        raise DescriptionCheckError(model.name, model.source, problems)
    links = dict(model.links)
    for name in names:
        shapes = tuple(_parts(c, parts_file) for c in links[name].collisions)
        links[name] = replace(links[name], collisions=shapes)
    return RobotModel(model.name, links, model.joints, model.source)


def _parts(collision: Collision, parts_file: PartsFile) -> Collision:
    geometry = collision.geometry
    if geometry.kind != "mesh":
        return collision
    path = parts_file(Path(geometry.filename), geometry.scale)
    return replace(collision, geometry=Geometry("mesh", filename=str(path)))

"""Which links of a fixed robot to collide as convex parts: those whose hull overreaches.

A mesh collides as its convex hull (PyBullet, the coal checks). How far that hull
reaches past the mesh is the farthest a point of the hull's surface lies from the mesh's
surface: 0 for a convex mesh, the depth of the biggest hollow the hull closes over for a
concave one (points sampled on each hull triangle, their distances to the mesh by coal).
Measured on the zoo's 30 robots (``benchmarks/robot_zoo.py``): Baxter's pedestal 0.27 m
and torso 0.17 m (its hull fills 0.24 m in front of the torso where the elbows swing: its
arms could not reach down to a table before it), the links rigid with the root of the
other fixed robots (Panda, Z1, SO-100, SO-101, UR5, UR3, Kinova, xArm, Tracy) 0.03 m or
less; over 0.1 m on mobile robots: the PR2's base 0.25 m, the TIAGos' 0.21 m, TIAGo
Pro's torso base 0.10 m, robots that reach the table with their hulls (their bases
stand back from it, and their arms reach out over their bases). So the
draft names, of a fixed robot only, the links rigid with its root whose hull reaches more
than :data:`OVERREACH` past their mesh; every other draft stays as it was.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import coal
else:
    coal = LazyLibrary("coal")

OVERREACH = 0.10  # [m] a hull reaching farther past its mesh: the link collides as parts
STEPS = 5  # samples along each edge of a hull triangle (15 a triangle)


@dataclass(frozen=True)
class Overreach:
    """The links to decompose and why (empty: none)."""

    links: tuple[str, ...]
    why: str


def overreaching_links(tree: ModelTree, fixed: bool) -> Overreach:
    """The links rigid with the root of a fixed robot whose hull reaches more than
    :data:`OVERREACH` past their collision mesh, in file order (none for a mobile one)."""
    if not fixed:
        return Overreach((), "")
    model = tree.model
    found: dict[str, float] = {}
    for link in sorted(tree.rigid_group(model.root_link), key=list(model.links).index):
        reaches = [
            hull_overreach(Path(c.geometry.filename), c.geometry.scale)
            for c in model.links[link].collisions
            if c.geometry.kind == "mesh" and Path(c.geometry.filename).is_file()
        ]
        if reaches and max(reaches) > OVERREACH:
            found[link] = max(reaches)
    if not found:
        return Overreach((), "")
    said = ", ".join(f"{link}'s {reach:.2f} m" for link, reach in found.items())
    why = (
        f"their collision meshes' convex hulls reach past the meshes ({said}; over "
        f"{OVERREACH:.2f} m): they collide as their convex parts, not as one hull"
    )
    return Overreach(tuple(found), why)


def hull_overreach(mesh: Path, scale: tuple[float, float, float]) -> float:
    """How far [m] the convex hull of ``mesh`` (scaled) reaches past the mesh's surface."""
    bvh = coal.MeshLoader().load(str(mesh), np.asarray(scale, dtype=float))
    points = np.array(bvh.vertices(), dtype=float).reshape(-1, 3)
    if len(points) < 4:
        return 0.0
    vertices = coal.StdVec_Vec3s()
    vertices.extend(np.ascontiguousarray(p) for p in points)
    try:
        hull = coal.Convex.convexHull(vertices, True, "Qt")
    except Exception:  # noqa: BLE001 - a vertex with too many neighbours: joggled
        hull = coal.Convex.convexHull(vertices, True, "QJ")
    corners = np.array([hull.point(i) for i in range(hull.num_points)], dtype=float)
    probe = coal.Sphere(1e-9)
    request = coal.DistanceRequest()
    origin = coal.Transform3s()
    farthest = 0.0
    for sample in _samples(corners, hull):
        where = coal.Transform3s()
        where.setTranslation(sample)
        distance = coal.distance(bvh, origin, probe, where, request, coal.DistanceResult())
        farthest = max(farthest, float(distance))
    return farthest


def _samples(corners: NDArray[np.float64], hull: coal.ConvexBase) -> NDArray[np.float64]:
    """Points spread over each triangle of the hull (corners, edges and inside)."""
    weights = [
        (u, v) for u in np.linspace(0.0, 1.0, STEPS) for v in np.linspace(0.0, 1.0 - u, STEPS)
    ]
    found = []
    for index in range(hull.num_polygons):
        triangle = hull.polygons(index)
        a, b, c = (corners[triangle[k]] for k in range(3))
        found += [a + u * (b - a) + v * (c - a) for u, v in weights]
    return np.array(found, dtype=float).reshape(-1, 3)

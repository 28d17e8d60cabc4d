"""Coal geometry for collision shapes, meshes as convex hulls like PyBullet's.

PyBullet collides a mesh of a moving body with its convex hull, and an OBJ file with one
hull per object (``o``) or group (``g``) in it (a mug: the cup and each handle piece).
Coal makes the same hulls here, so both engines see the same shapes. Hulls are cached per
process by file and scale: they are read-only and scenes share them. The points of each
part are kept on disk by the file's content, so a new process does not load the mesh.
"""

from __future__ import annotations

import functools
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.motion.errors import MotionError
from robocram.robots.disk_cache import file_key, kept_arrays
from robocram.robots.lazy_library import LazyLibrary
from robocram.tf import Vector3

if TYPE_CHECKING:
    import coal
else:
    coal = LazyLibrary("coal")

_BUILT_BY = ("robocram.motion.coal_shapes",)  # what computes the kept mesh parts
# The floor: a half-space z <= 0 of its frame.
_UP = np.array([0.0, 0.0, 1.0])


def coal_geometries(
    kind: str, extents: Vector3, mesh: str = ""
) -> tuple[coal.CollisionGeometry, ...]:
    """The coal geometry (several for an OBJ of many parts) of one collision shape.

    ``extents`` [m] as :class:`~robocram.world.CollisionShape` gives them: a box's full
    extents, a cylinder's (2 r, 2 r, length), a sphere's (2 r, 2 r, 2 r), a mesh's scale.
    """
    x, y, z = (float(v) for v in extents)
    if kind == "box":
        return (coal.Box(x, y, z),)
    if kind == "cylinder":
        return (coal.Cylinder(x / 2, z),)
    if kind == "sphere":
        return (coal.Sphere(x / 2),)
    if kind == "plane":
        return (coal.Halfspace(_UP, 0.0),)
    if kind == "mesh":
        return mesh_hulls(mesh, (x, y, z))
    raise MotionError(f"unknown collision shape kind {kind!r}; use box, cylinder, sphere, mesh")


@functools.lru_cache(maxsize=512)
def mesh_hulls(path: str, scale: Vector3) -> tuple[coal.ConvexBase, ...]:
    """Convex hulls of a mesh file scaled by ``scale``: one per part of an OBJ, else one."""
    file = Path(path)
    if not file.is_file():
        raise MotionError(f"mesh file {path} does not exist; fix the URDF or the object's spec")
    factor = np.asarray(scale, dtype=float)
    parts = _kept_parts(file)
    return tuple(_hull(points * factor, path) for points in parts if len(points) >= 4)


def _kept_parts(file: Path) -> list[NDArray[np.float64]]:
    """The vertices of each part of a mesh file, kept on disk by the file's content: coal's
    mesh loader builds a BVH a hull does not need (most of a hull's cost, ~1 ms a mesh)."""
    kept = kept_arrays(
        "mesh_parts", f"mesh {file_key(file)} {file.suffix.lower()}", _BUILT_BY,
        lambda: _parts_arrays(file), versions=(coal.__version__,),
    )  # fmt: skip
    ends = np.cumsum(kept["counts"])[:-1]
    return np.split(np.asarray(kept["points"], dtype=float), ends)


def _parts_arrays(file: Path) -> dict[str, NDArray[np.float64] | NDArray[np.int64]]:
    parts = _obj_parts(file) if file.suffix.lower() == ".obj" else [_loaded_vertices(file)]
    return {
        "points": np.concatenate(parts) if parts else np.zeros((0, 3)),
        "counts": np.array([len(p) for p in parts], dtype=np.int64),
    }


def _loaded_vertices(file: Path) -> NDArray[np.float64]:
    try:
        bvh = coal.MeshLoader().load(str(file), np.ones(3))
    except Exception as err:  # coal raises plain RuntimeErrors for unreadable meshes
        raise MotionError(f"coal cannot read mesh {file}: {err}") from err
    return np.array(bvh.vertices(), dtype=float).reshape(-1, 3)


def _obj_parts(file: Path) -> list[NDArray[np.float64]]:
    """The vertices each ``o``/``g`` part of an OBJ file's faces use, part by part."""
    vertices: list[tuple[float, float, float]] = []
    parts: list[set[int]] = [set()]
    for line in file.read_text(encoding="utf-8", errors="replace").splitlines():
        words = line.split()
        if not words:
            continue
        if words[0] == "v":
            vertices.append((float(words[1]), float(words[2]), float(words[3])))
        elif words[0] in ("o", "g") and parts[-1]:
            parts.append(set())
        elif words[0] == "f":
            for word in words[1:]:
                index = int(word.split("/")[0])
                parts[-1].add(index - 1 if index > 0 else len(vertices) + index)
    table = np.array(vertices, dtype=float).reshape(-1, 3)
    return [table[sorted(part)] for part in parts if part]


def _hull(points: NDArray[np.float64], path: str) -> coal.ConvexBase:
    try:
        return coal.Convex.convexHull(_vec3s(points), False, "Qt")
    except Exception:  # noqa: BLE001 - triangulated, a vertex may get too many neighbours
        pass  # (Centauro's pelvis): joggled, qhull gives a hull coal takes
    try:
        return coal.Convex.convexHull(_vec3s(points), False, "QJ")
    except Exception as err:  # qhull refuses flat or degenerate point sets
        raise MotionError(f"no convex hull of a part of mesh {path}: {err}") from err


def _vec3s(points: NDArray[np.float64]) -> coal.StdVec_Vec3s:
    vector = coal.StdVec_Vec3s()
    vector.extend(np.ascontiguousarray(p) for p in points)
    return vector

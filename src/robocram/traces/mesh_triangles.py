"""A mesh file's triangles, for markers that carry their geometry with them.

An export that names a mesh by its path shows nothing on a machine without that file;
one that carries the triangles shows the same everywhere. Meshes are read with trimesh
(the ``mcap`` and ``viewer`` extras), once per file and scale. A mesh of more than
:data:`MAX_TRIANGLES` is not embedded: its bounding box stands in, so an export stays a
few megabytes (the PR2's visuals are 27,561 triangles, about 2 MB).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

from robocram.traces.errors import TraceError

MAX_TRIANGLES = 50_000  # per mesh file
Point = tuple[float, float, float]


@dataclass(frozen=True)
class MeshBox:
    """A mesh too big to embed: the extents [m] of its bounding box, about its centre."""

    size: Point
    centre: Point

    def triangles(self) -> tuple[Point, ...]:
        """The box's twelve triangles (two per face), three corners each."""
        (cx, cy, cz), (hx, hy, hz) = self.centre, (s / 2 for s in self.size)
        corner: list[Point] = [
            (cx + (hx if k & 1 else -hx), cy + (hy if k & 2 else -hy), cz + (hz if k & 4 else -hz))
            for k in range(8)
        ]
        found: list[Point] = []
        for a, b, c, d in _FACES:
            found += [corner[a], corner[b], corner[c], corner[a], corner[c], corner[d]]
        return tuple(found)


_FACES = ((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3))


@functools.lru_cache(maxsize=512)
def mesh_triangles(filename: str, scale: Point) -> tuple[Point, ...] | MeshBox:
    """The corners of ``filename``'s triangles, three per triangle, scaled by ``scale``
    [m per unit]; a :class:`MeshBox` when there are more than :data:`MAX_TRIANGLES`.

    Raises:
        TraceError: the file is missing or not a mesh trimesh reads.
    """
    try:
        import trimesh  # the mcap and viewer extras
    except ImportError as err:
        raise TraceError("embedding meshes needs trimesh: pip install 'robocram[mcap]'") from err
    try:
        mesh = trimesh.load(filename, force="mesh")
    except (OSError, ValueError) as err:
        raise TraceError(f"mesh {filename} cannot be read: {err}") from err
    if not isinstance(mesh, trimesh.Trimesh):  # force="mesh" merges a scene into one mesh
        raise TraceError(f"mesh {filename} holds no triangles")
    vertices = mesh.vertices * scale
    if len(mesh.faces) > MAX_TRIANGLES:
        low, high = vertices.min(axis=0), vertices.max(axis=0)
        size = high - low
        centre = (low + high) / 2
        return MeshBox(
            (float(size[0]), float(size[1]), float(size[2])),
            (float(centre[0]), float(centre[1]), float(centre[2])),
        )
    corners = vertices[mesh.faces.reshape(-1)]
    return tuple((float(x), float(y), float(z)) for x, y, z in corners)

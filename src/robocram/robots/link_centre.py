"""Where a link's body is: the centre of its collision shapes, in the link's own frame.

A revolute jaw's link frame sits on its pivot, so the frame does not move when the jaw
opens; the middle of the jaw does. The gripper's opening direction and widest opening of a
single moving jaw (Unitree's Z1, the SO-101) are measured at this centre. Meshes are read
for their bounding box without a mesh library: binary and ASCII STL, OBJ and COLLADA
vertex positions (COLLADA in its unit); a mesh that cannot be read (missing, another
format) counts as the link frame's origin.
"""

from __future__ import annotations

import itertools
import re
import struct
from functools import lru_cache
from pathlib import Path

import numpy as np

from robocram.robots.urdf_elements import Collision, Geometry, Link
from robocram.tf import Pose

Box = tuple[tuple[float, float, float], tuple[float, float, float]]
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_COLLADA_UNIT = re.compile(rf"<unit[^>]*meter=\"({_NUMBER})\"", re.IGNORECASE)
_COLLADA_POSITIONS = re.compile(
    r"<float_array[^>]*id=\"[^\"]*position[^\"]*\"[^>]*>([^<]*)</float_array>", re.IGNORECASE
)


def _stl_points(data: bytes) -> np.ndarray | None:
    if len(data) >= 84:
        count = struct.unpack_from("<I", data, 80)[0]
        if 84 + 50 * count == len(data) and count > 0:
            records = np.frombuffer(data, dtype=np.uint8, offset=84).reshape(count, 50)
            floats = records[:, 12:48].copy().view("<f4").reshape(count * 3, 3)
            return floats.astype(float)
    text = data.decode("ascii", errors="ignore")
    found = re.findall(rf"vertex\s+({_NUMBER})\s+({_NUMBER})\s+({_NUMBER})", text)
    return np.asarray(found, float) if found else None


def _obj_points(text: str) -> np.ndarray | None:
    found = re.findall(rf"^v\s+({_NUMBER})\s+({_NUMBER})\s+({_NUMBER})", text, flags=re.MULTILINE)
    return np.asarray(found, float) if found else None


def _collada_points(text: str) -> np.ndarray | None:
    arrays = [np.asarray(block.split(), float) for block in _COLLADA_POSITIONS.findall(text)]
    points = [a.reshape(-1, 3) for a in arrays if a.size and a.size % 3 == 0]
    unit = _COLLADA_UNIT.search(text)
    scale = float(unit.group(1)) if unit else 1.0
    return np.vstack(points) * scale if points else None


@lru_cache(maxsize=64)
def mesh_points(filename: str) -> np.ndarray | None:
    """The vertices [m, unscaled, N x 3] of a mesh file, or None if it cannot be read.

    COLLADA files are read in their unit but without their node transforms, which
    suffices for the middle of a finger; STL and OBJ are exact.
    """
    path = Path(filename)
    try:
        data = path.read_bytes()
    except OSError:
        return None
    suffix = path.suffix.lower()
    if suffix == ".stl":
        points = _stl_points(data)
    elif suffix == ".obj":
        points = _obj_points(data.decode("utf-8", errors="ignore"))
    elif suffix == ".dae":
        points = _collada_points(data.decode("utf-8", errors="ignore"))
    else:
        points = None
    if points is None or not len(points) or not np.isfinite(points).all():
        return None
    points.setflags(write=False)
    return points


@lru_cache(maxsize=256)
def mesh_box(filename: str) -> Box | None:
    """Bounding box [m, unscaled] of a mesh file's vertices, or None if it cannot be read."""
    points = mesh_points(filename)
    if points is None:
        return None
    low, high = points.min(axis=0), points.max(axis=0)
    return (
        (float(low[0]), float(low[1]), float(low[2])),
        (float(high[0]), float(high[1]), float(high[2])),
    )


def _shape_box(geometry: Geometry) -> Box | None:
    """The shape's bounding box in its own frame."""
    if geometry.kind == "mesh":
        box = mesh_box(geometry.filename)
        if box is None:
            return None
        scale = np.asarray(geometry.scale)
        corners = np.asarray(box) * scale
        low, high = corners.min(axis=0), corners.max(axis=0)
        return (tuple(float(v) for v in low), tuple(float(v) for v in high))  # type: ignore[return-value]
    extents = geometry.extents()
    if extents is None:
        return None
    half = tuple(e / 2 for e in extents)
    return ((-half[0], -half[1], -half[2]), (half[0], half[1], half[2]))


def _corners(collision: Collision) -> list[np.ndarray]:
    box = _shape_box(collision.geometry)
    if box is None:
        return []
    return [
        np.asarray((collision.origin * Pose((x, y, z))).position)
        for x, y, z in itertools.product(*zip(*box, strict=True))
    ]


def link_box(link: Link) -> Box | None:
    """The box [m, link frame] around ``link``'s collision shapes, or None (none readable)."""
    corners = [c for collision in link.collisions for c in _corners(collision)]
    if not corners:
        return None
    stacked = np.asarray(corners)
    low, high = stacked.min(axis=0), stacked.max(axis=0)
    return (
        (float(low[0]), float(low[1]), float(low[2])),
        (float(high[0]), float(high[1]), float(high[2])),
    )


def link_centre(link: Link) -> tuple[float, float, float]:
    """Centre [m, link frame] of the bounding box of ``link``'s collision shapes.

    The link frame's origin when it has none (or none whose size can be read).
    """
    box = link_box(link)
    if box is None:
        return (0.0, 0.0, 0.0)
    centre = (np.asarray(box[0]) + np.asarray(box[1])) / 2
    return (float(centre[0]), float(centre[1]), float(centre[2]))


def link_points(link: Link) -> np.ndarray | None:
    """Points [m, link frame, N x 3] on ``link``'s collision shapes: a mesh's vertices, a
    primitive's box corners; None when it has no shape whose size can be read. Where a
    jaw's face lies needs the shape, which a box around a jaw and its housing hides."""
    found: list[np.ndarray] = []
    for collision in link.collisions:
        geometry = collision.geometry
        vertices = mesh_points(geometry.filename) if geometry.kind == "mesh" else None
        if vertices is None:
            found += [c[None, :] for c in _corners(collision)]
            continue
        scaled = vertices * np.asarray(geometry.scale)
        matrix = collision.origin.matrix()
        found.append(scaled @ matrix[:3, :3].T + matrix[:3, 3])
    return np.vstack(found) if found else None

"""Rays against one body alone, computed from its collision shapes without the physics engine.

Visibility asks where rays would meet an object if nothing else were there. Bullet answers
that slowly for meshes (a GJK cast per ray and convex part, ~20 us each: the catalogue mug
has six parts), so the lone test is done here in numpy. Each collision piece is a convex
solid: a box, sphere or cylinder, a convex hull per part of an OBJ mesh (as pybullet
builds them), or the hull pybullet makes of a URDF cylinder. It is placed by its link's
pose now, and a ray enters it at the largest entering and leaves at the smallest leaving
distance over its faces. Shapes not modelled here (planes, capsules, height fields, STL
or DAE files) give None, and callers ask Bullet instead.
"""

from __future__ import annotations

import functools
import hashlib
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.robots.disk_cache import file_key, kept_arrays
from robocram.tf import Pose
from robocram.world.errors import WorldValueError
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_object import WorldObject

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade

FloatArray = NDArray[np.float64]
HULL_TOLERANCE = 1e-7  # [m] points this close to a face plane lie on it
HULL_MARGIN = 0.001  # [m] pybullet's collision margin around the convex hulls of meshes
_KIND = "ray_hulls"  # the disk cache's folder for the hulls below
_BUILT_BY = ("robocram.world.shape_rays",)


@dataclass(frozen=True, eq=False)
class Piece:
    """One convex piece in its own frame: ``planes`` (F x 4, ``n . x <= d``) and/or a round
    part (``radius`` [m] about the z axis for a cylinder, about the origin for a sphere).

    ``kind`` is ``"planes"``, ``"sphere"`` or ``"cylinder"`` (planes then hold the caps).
    ``box`` [m] holds the piece: its lower and upper corner (2 x 3) in the piece's frame.
    """

    kind: str
    planes: FloatArray
    radius: float
    box: FloatArray

    def entry(self, origins: FloatArray, dirs: FloatArray) -> FloatArray:
        """Distance along each ray (unit ``dirs``, piece frame) where it enters; inf if never."""
        t_in = np.full(len(origins), -np.inf)
        t_out = np.full(len(origins), np.inf)
        if len(self.planes):
            normals, offsets = self.planes[:, :3], self.planes[:, 3]
            denom = dirs @ normals.T  # K x F
            with np.errstate(divide="ignore", invalid="ignore"):
                t = (offsets[None, :] - origins @ normals.T) / denom
            # parallel to a face: +inf inside its plane (no bound), -inf outside (a miss)
            entering = denom < 0
            t_in = np.where(entering, t, -np.inf).max(axis=1)
            t_out = np.fmin.reduce(np.where(entering, np.inf, t), axis=1)
        if self.kind != "planes":
            axes = slice(0, 2) if self.kind == "cylinder" else slice(0, 3)
            o, v = origins[:, axes], dirs[:, axes]
            a = (v * v).sum(axis=1)
            b = (o * v).sum(axis=1)
            c = (o * o).sum(axis=1) - self.radius**2
            disc = b * b - a * c
            with np.errstate(divide="ignore", invalid="ignore"):
                root = np.sqrt(np.maximum(disc, 0.0))
                lo, hi = (-b - root) / a, (-b + root) / a
            along = a < 1e-12  # a ray along a cylinder's axis: inside or outside for good
            lo = np.where(along, np.where(c <= 0, -np.inf, np.inf), lo)
            hi = np.where(along, np.where(c <= 0, np.inf, -np.inf), hi)
            lo[disc < 0], hi[disc < 0] = np.inf, -np.inf
            t_in, t_out = np.maximum(t_in, lo), np.minimum(t_out, hi)
        hit = (t_in <= t_out) & (t_out >= 0)
        return np.where(hit, np.maximum(t_in, 0.0), np.inf)


@dataclass(frozen=True, eq=False)
class LoneBody:
    """A body's convex pieces, each with its pose in the world now."""

    pieces: tuple[tuple[Piece, Pose], ...]

    def first_hit(self, origins: FloatArray, dirs: FloatArray, length: FloatArray) -> FloatArray:
        """Distance [m] at which each ray (world frame, unit ``dirs``) first meets the body,
        inf when it does not within its ``length``.

        Every piece's box is tested against every ray in one pass (a mug has six pieces:
        six passes cost twice as much); only the rays through a piece's box enter it.
        """
        best = np.full(len(origins), np.inf)
        if not self.pieces:
            return best
        rotations, centres, boxes = self._frames()
        local_origins = (origins[None, :, :] - centres[:, None, :]) @ rotations
        local_dirs = dirs[None, :, :] @ rotations
        through = _box_hits(boxes, local_origins, local_dirs, length)
        for k, (piece, _) in enumerate(self.pieces):
            near = np.flatnonzero(through[k])
            if len(near) == 0:
                continue
            t = piece.entry(local_origins[k, near], local_dirs[k, near])
            best[near] = np.minimum(best[near], t)
        best[best > length] = np.inf
        return best

    def _frames(self) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Per piece: its rotation (3 x 3) and origin in the world, and its box (2 x 3)."""
        matrices = np.array([pose.matrix() for _, pose in self.pieces])
        boxes = np.array([piece.box for piece, _ in self.pieces], dtype=float)
        return matrices[:, :3, :3], matrices[:, :3, 3], boxes


def _box_hits(
    boxes: FloatArray, origins: FloatArray, dirs: FloatArray, length: FloatArray
) -> NDArray[np.bool_]:
    """``[piece, ray]``: whether the ray passes through the piece's axis-aligned box
    (``boxes`` (pieces, 2, 3); rays (pieces, rays, 3) in each piece's frame) within its
    ``length`` (slabs; a ray in a slab's plane leaves that slab out)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        inverse = 1.0 / dirs
        low = (boxes[:, 0, None, :] - origins) * inverse
        high = (boxes[:, 1, None, :] - origins) * inverse
    enter = np.fmax.reduce(np.minimum(low, high), axis=2)  # NaN (0 * inf) ignored
    leave = np.fmin.reduce(np.maximum(low, high), axis=2)
    return np.asarray((enter <= leave) & (leave >= 0) & (enter <= length[None, :]))


def lone_body(world: WorldFacade, obj: WorldObject) -> LoneBody | None:
    """``obj``'s collision pieces where they are now; None if one of them is not modelled."""
    cid = world.physics.client()
    placed: list[tuple[Piece, Pose]] = []
    for body, link in _all_links(obj, cid):
        shapes = pybullet.getCollisionShapeData(body, link, physicsClientId=cid)
        if not shapes:
            continue
        inertial = _inertial_pose(body, link, cid)
        for index, shape in enumerate(shapes):
            pieces = _pieces(shape[2], tuple(shape[3]), shape[4])
            if pieces is None and shape[2] == pybullet.GEOM_MESH and shape[4] == b"unknown_file":
                # a URDF cylinder pybullet made a convex mesh of: its vertices, from Bullet
                data = pybullet.getMeshData(
                    body, link, collisionShapeIndex=index, physicsClientId=cid
                )
                pieces = (_vertex_hull(tuple(map(tuple, data[1]))),) if data[0] >= 4 else None
            if pieces is None:
                return None
            frame = inertial * Pose(tuple(shape[5]), tuple(shape[6]))
            placed.extend((piece, frame) for piece in pieces)
    return LoneBody(tuple(placed))


def _all_links(obj: WorldObject, cid: int) -> list[tuple[int, int]]:
    """``(body, pybullet link index)`` of every link of every body of ``obj``."""
    return [
        (body, link)
        for body in obj.bodies
        for link in (-1, *range(pybullet.getNumJoints(body, physicsClientId=cid)))
    ]


def _inertial_pose(body: int, link: int, cid: int) -> Pose:
    """World pose of a link's inertial frame, the frame collision shapes are given in."""
    if link == -1:
        pos, orn = pybullet.getBasePositionAndOrientation(body, physicsClientId=cid)
    else:
        pos, orn = pybullet.getLinkState(body, link, physicsClientId=cid)[:2]
    return Pose(tuple(pos), tuple(orn))


def _pieces(geometry: int, size: tuple[float, ...], filename: bytes) -> tuple[Piece, ...] | None:
    """The convex pieces of one collision shape (pybullet's ``getCollisionShapeData`` row)."""
    if geometry == pybullet.GEOM_BOX:
        return (_box(np.asarray(size[:3], dtype=float) / 2),)
    if geometry == pybullet.GEOM_SPHERE:
        r = size[0]
        return (Piece("sphere", np.zeros((0, 4)), r, np.array([[-r, -r, -r], [r, r, r]])),)
    if geometry == pybullet.GEOM_CYLINDER:
        return (_cylinder(size[1], size[0] / 2),)
    if geometry == pybullet.GEOM_MESH and filename.lower().endswith(b".obj"):
        return _mesh_hulls(filename.decode(), tuple(float(s) for s in size[:3]))
    return None


def _box(half: FloatArray) -> Piece:
    normals = np.vstack([np.eye(3), -np.eye(3)])
    planes = np.column_stack([normals, np.concatenate([half, half])])
    return Piece("planes", planes, 0.0, np.array([-half, half]))


def _cylinder(radius: float, half: float) -> Piece:
    caps = np.array([[0.0, 0.0, 1.0, half], [0.0, 0.0, -1.0, half]])
    return Piece(
        "cylinder", caps, radius, np.array([[-radius, -radius, -half], [radius, radius, half]])
    )


@functools.lru_cache(maxsize=64)
def _mesh_hulls(path: str, scale: tuple[float, float, float]) -> tuple[Piece, ...] | None:
    """One convex hull per object (``o``/``g`` group) of an OBJ file, as pybullet builds them;
    kept on disk by the file's content, so a new process reads them instead (tens of ms)."""
    file = Path(path)
    key = f"obj {file_key(file)} scale {scale!r}"
    kept = kept_arrays(_KIND, key, _BUILT_BY, lambda: _hull_arrays(_mesh_pieces(file, scale)))
    return _pieces_of(kept) or None


def _mesh_pieces(file: Path, scale: tuple[float, float, float]) -> tuple[Piece, ...]:
    return tuple(_hull(points * np.asarray(scale)) for points in _obj_groups(file))


@functools.lru_cache(maxsize=256)
def _vertex_hull(vertices: tuple[tuple[float, ...], ...]) -> Piece:
    """The convex hull of a mesh pybullet built itself (no file to read), kept on disk by
    its vertices."""
    points = np.asarray(vertices, dtype=float)
    key = f"vertices {hashlib.sha256(points.tobytes()).hexdigest()} {points.shape}"
    kept = kept_arrays(_KIND, key, _BUILT_BY, lambda: _hull_arrays((_hull(points),)))
    (piece,) = _pieces_of(kept)
    return piece


def _hull_arrays(pieces: tuple[Piece, ...]) -> dict[str, FloatArray | NDArray[np.int64]]:
    """Hull pieces as the arrays of a disk cache entry: their planes end to end, the count
    of planes of each and their boxes."""
    return {
        "planes": np.concatenate([p.planes for p in pieces]) if pieces else np.zeros((0, 4)),
        "counts": np.array([len(p.planes) for p in pieces], dtype=np.int64),
        "boxes": np.array([p.box for p in pieces]).reshape(-1, 2, 3),
    }


def _pieces_of(kept: Mapping[str, NDArray[np.generic]]) -> tuple[Piece, ...]:
    """The hull pieces :func:`_hull_arrays` stored."""
    ends = np.cumsum(kept["counts"])
    planes = np.split(np.asarray(kept["planes"], dtype=float), ends[:-1]) if len(ends) else []
    boxes = np.asarray(kept["boxes"], dtype=float)
    return tuple(
        Piece("planes", np.array(p), 0.0, np.array(b)) for p, b in zip(planes, boxes, strict=True)
    )


def _obj_groups(path: Path) -> list[FloatArray]:
    """The vertices each face group of an OBJ file uses (the whole file if it has no groups)."""
    vertices: list[tuple[float, float, float]] = []
    groups: list[set[int]] = [set()]
    for line in path.read_text(errors="replace").splitlines():
        head, _, rest = line.partition(" ")
        if head == "v":
            x, y, z = (float(v) for v in rest.split()[:3])
            vertices.append((x, y, z))
        elif head in ("o", "g") and groups[-1]:
            groups.append(set())
        elif head == "f":
            for corner in rest.split():
                index = int(corner.split("/")[0])
                groups[-1].add(index - 1 if index > 0 else len(vertices) + index)
    table = np.asarray(vertices, dtype=float)
    return [table[sorted(g)] for g in groups if len(g) >= 4]


def _hull(points: FloatArray) -> Piece:
    """The face planes of the convex hull of ``points`` (outward normals), incrementally.

    Points within :data:`HULL_TOLERANCE` of the hull so far are left out: the hull is then
    at most that much smaller than the exact one.
    """
    points = np.unique(points, axis=0)
    faces = _tetrahedron(points)
    for index in range(len(points)):
        planes = _face_planes(points, faces)
        seen = planes[:, :3] @ points[index] - planes[:, 3] > HULL_TOLERANCE
        if not seen.any():
            continue
        lit = [f for f, s in zip(faces, seen, strict=True) if s]
        edges = {(f[i], f[(i + 1) % 3]) for f in lit for i in range(3)}
        horizon = [(a, b) for a, b in edges if (b, a) not in edges]
        faces = [f for f, s in zip(faces, seen, strict=True) if not s]
        faces.extend((a, b, index) for a, b in horizon)
    planes = np.unique(np.round(_face_planes(points, faces), 6), axis=0)  # coplanar: once
    planes[:, 3] += HULL_MARGIN
    box = np.array([points.min(axis=0) - HULL_MARGIN, points.max(axis=0) + HULL_MARGIN])
    return Piece("planes", planes, 0.0, box)


def _tetrahedron(points: FloatArray) -> list[tuple[int, int, int]]:
    """Four faces (counter-clockwise seen from outside) of a tetrahedron of ``points``."""
    a = 0
    b = int(np.argmax(np.linalg.norm(points - points[a], axis=1)))
    line = points[b] - points[a]
    c = int(np.argmax(np.linalg.norm(np.cross(points - points[a], line), axis=1)))
    normal = np.cross(line, points[c] - points[a])
    d = int(np.argmax(np.abs((points - points[a]) @ normal)))
    if abs(float((points[d] - points[a]) @ normal)) < HULL_TOLERANCE:
        raise WorldValueError("a mesh part is flat: it has no convex volume to hit")
    if (points[d] - points[a]) @ normal > 0:
        b, c = c, b  # so that (a, b, c) faces away from d
    return [(a, b, c), (a, d, b), (b, d, c), (c, d, a)]


def _face_planes(points: FloatArray, faces: list[tuple[int, int, int]]) -> FloatArray:
    """``(n, d)`` per face: unit outward normal and offset, ``n . x <= d`` inside."""
    tri = points[np.array(faces)]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    return np.column_stack([normals, np.einsum("ij,ij->i", normals, tri[:, 0])])

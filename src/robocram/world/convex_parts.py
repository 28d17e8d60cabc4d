"""The convex parts of a robot's mesh, by PyBullet's V-HACD, kept on disk once per machine.

A description's ``decomposed_links`` collide as their meshes' convex parts
(:mod:`robocram.robots.convex_parts`); the parts are made here because only this layer
calls PyBullet. V-HACD reads and writes OBJ files only, so the mesh (any format coal's
loader reads: Baxter's torso is a COLLADA file) goes in as a scaled OBJ; the parts come
back as one OBJ with an object (``o``) per part, which PyBullet loads as a compound of
hulls and ``motion/coal_shapes.py`` reads part by part. Parts are kept in the disk cache
(``robots/disk_cache.py``) by the mesh's bytes, its scale and the parameters, and the
OBJ is named by the parts' own bytes: V-HACD gives the same parts each run (measured on
Baxter's torso), and a second process reads them (1.7 s saved).
"""

from __future__ import annotations

import dataclasses
import hashlib
import os
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.robots import LoadedDescription
from robocram.robots.convex_parts import with_convex_parts
from robocram.robots.disk_cache import cache_dir, file_key, kept_arrays
from robocram.robots.lazy_library import LazyLibrary
from robocram.world.errors import WorldValueError
from robocram.world.pybullet_backend import pybullet, silenced

if TYPE_CHECKING:
    import coal
else:
    coal = LazyLibrary("coal")

# V-HACD's voxels: its default (1e6) takes 8.4 s on Baxter's torso for 15 parts; 2e5 takes
# 1.7 s for 8 parts, with which its pick-up and workcell complete (zoo33, zoo36)
RESOLUTION = 200_000
KIND = "convex_parts"


def decomposed(description: LoadedDescription) -> LoadedDescription:
    """``description`` with its ``decomposed_links`` colliding as convex parts (itself
    when it names none: the built-in robots load as they always did)."""
    if not description.decomposed_links:
        return description
    model = with_convex_parts(description.model, description.decomposed_links, convex_parts_file)
    if model is description.model:
        return description
    return dataclasses.replace(description, model=model)


def convex_parts_file(mesh: Path, scale: tuple[float, float, float]) -> Path:
    """An OBJ file of the convex parts of ``mesh`` scaled by ``scale``, one object each.

    Raises:
        WorldValueError: the mesh is missing, unreadable, or V-HACD finds no part in it.
    """
    if not mesh.is_file():
        raise WorldValueError(f"mesh file {mesh} does not exist; fix the URDF's collision mesh")
    key = f"mesh {file_key(mesh)} {mesh.suffix.lower()} scale {scale} resolution {RESOLUTION}"
    arrays = kept_arrays(
        KIND, key, [__name__], lambda: _decomposition(mesh, scale),
        versions=(str(pybullet.getAPIVersion()),),
    )  # fmt: skip
    text = _obj_text(arrays)
    name = f"{mesh.stem}-{hashlib.sha256(text.encode('utf-8')).hexdigest()[:32]}.obj"
    try:
        return _written(cache_dir() / KIND / name, text)
    except OSError:  # a cache that cannot be written (a read-only home): the temp folder
        return _written(Path(tempfile.gettempdir()) / f"robocram-{KIND}" / name, text)


def _written(path: Path, text: str) -> Path:
    """``path`` holding ``text``: written under a temporary name and renamed into place, so
    processes writing it at once each leave a whole file."""
    if not path.is_file():
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, temporary = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            out.write(text)
        os.replace(temporary, path)
    return path


def _decomposition(mesh: Path, scale: tuple[float, float, float]) -> dict[str, NDArray[np.generic]]:
    """The parts' vertices, faces (indices into the part's own vertices) and counts."""
    try:
        bvh = coal.MeshLoader().load(str(mesh), np.asarray(scale, dtype=float))
    except Exception as err:  # coal raises plain RuntimeErrors for unreadable meshes
        raise WorldValueError(f"cannot read mesh {mesh} to decompose it: {err}") from err
    points = np.array(bvh.vertices(), dtype=float).reshape(-1, 3)
    faces = np.array(
        [[bvh.tri_indices(i)[k] for k in range(3)] for i in range(bvh.num_tris)], dtype=np.int64
    ).reshape(-1, 3)
    with tempfile.TemporaryDirectory() as folder:
        source, parts, log = (str(Path(folder) / n) for n in ("in.obj", "out.obj", "log.txt"))
        Path(source).write_text(_obj_lines([points], [faces]), encoding="utf-8")
        with silenced():  # V-HACD reports its progress on the C stdout
            pybullet.vhacd(source, parts, log, resolution=RESOLUTION)
        found = _read_obj(Path(parts)) if Path(parts).is_file() else []
    if not found:
        raise WorldValueError(
            f"V-HACD found no convex part in mesh {mesh}; leave it out of decomposed_links"
        )
    return {
        "points": np.concatenate([p for p, _ in found]),
        "faces": np.concatenate([f for _, f in found]),
        "point_counts": np.array([len(p) for p, _ in found], dtype=np.int64),
        "face_counts": np.array([len(f) for _, f in found], dtype=np.int64),
    }


def _read_obj(file: Path) -> list[tuple[NDArray[np.float64], NDArray[np.int64]]]:
    """Each object of a V-HACD OBJ: its vertices and its triangles (indices into them)."""
    vertices: list[list[float]] = []
    objects: list[list[list[int]]] = [[]]
    for line in file.read_text(encoding="utf-8").splitlines():
        words = line.split()
        if words and words[0] == "v":
            vertices.append([float(w) for w in words[1:4]])
        elif words and words[0] == "o" and objects[-1]:
            objects.append([])
        elif words and words[0] == "f":
            objects[-1].append([int(w.split("/")[0]) - 1 for w in words[1:4]])
    table = np.array(vertices, dtype=float).reshape(-1, 3)
    found = []
    for triangles in objects:
        if not triangles:
            continue
        used = np.unique(np.array(triangles, dtype=np.int64))
        local = np.searchsorted(used, np.array(triangles, dtype=np.int64))
        found.append((table[used], local))
    return found


def _obj_text(arrays: dict[str, NDArray[np.generic]]) -> str:
    point_ends = np.cumsum(arrays["point_counts"])[:-1]
    face_ends = np.cumsum(arrays["face_counts"])[:-1]
    points = np.split(np.asarray(arrays["points"], dtype=float), point_ends)
    faces = np.split(np.asarray(arrays["faces"], dtype=np.int64), face_ends)
    return _obj_lines(points, faces)


def _obj_lines(points: list[NDArray[np.float64]], faces: list[NDArray[np.int64]]) -> str:
    """An OBJ text with one object per (vertices, triangles) pair."""
    lines: list[str] = []
    offset = 1
    for index, (part, triangles) in enumerate(zip(points, faces, strict=True)):
        lines.append(f"o part_{index}")
        lines += [f"v {x:.9g} {y:.9g} {z:.9g}" for x, y, z in part]
        lines += [f"f {a + offset} {b + offset} {c + offset}" for a, b, c in triangles]
        offset += len(part)
    return "\n".join(lines) + "\n"

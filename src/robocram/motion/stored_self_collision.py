"""Self-collision matrices of the built-in robots, stored with their descriptions.

Working a matrix out samples a thousand configurations on PyBullet's shapes: ~0.4 s for
the PR2, paid by the first motion of each robot in a process (a script's first result,
every batch worker). MoveIt's setup assistant writes its matrix into the robot's SRDF
once; here the built-in robots' matrices are JSON files next to their descriptions
(``robots/builtin/self_collision/<name>.json``), each with a digest of what it was worked
out from: the URDF as loaded and what of the description the matrix reads. A stored
matrix is used only while its digest matches, so a changed URDF or parking pose works the
matrix out again; ``python tools/store_self_collision.py`` writes the files anew.
"""

from __future__ import annotations

import hashlib
import json
import re
from importlib import resources
from pathlib import Path, PurePosixPath

from robocram.robots import LoadedDescription, RobotModel

FOLDER = "self_collision"  # under robocram.robots.builtin
VERSION = 1  # of the file's layout and of how the matrix is worked out
MESH_FILE = re.compile(r'filename="([^"]*)"')
MESH_NAME_PARTS = 4  # a mesh is named by its package's folder, ...: pr2_description/meshes/...


def matrix_digest(desc: LoadedDescription, key: tuple[object, ...]) -> str:
    """The SHA-1 of what ``desc``'s matrix is worked out from: the loaded URDF text,
    ``key`` (what of the description it reads) and :data:`VERSION`."""
    urdf = desc.model.derived(_urdf_sha1)
    return hashlib.sha1(f"{VERSION}\n{urdf}\n{key!r}".encode()).hexdigest()


def _urdf_sha1(model: RobotModel) -> str:
    """The SHA-1 of the URDF as loaded, its mesh files named by their last
    :data:`MESH_NAME_PARTS` path parts: the same wherever the checkout or venv lies."""
    text = MESH_FILE.sub(_mesh_name, model.to_urdf())
    return hashlib.sha1(text.encode("utf-8")).hexdigest()


def _mesh_name(found: re.Match[str]) -> str:
    parts = PurePosixPath(found.group(1)).parts[-MESH_NAME_PARTS:]
    name = "/".join(parts)
    return f'filename="{name}"'


def stored_file(name: str) -> Path:
    """Where the built-in robot ``name``'s matrix is stored (whether or not it is)."""
    folder = resources.files("robocram.robots.builtin").joinpath(FOLDER)
    return Path(str(folder)) / f"{name}.json"


def read_stored(name: str, digest: str) -> dict[str, object] | None:
    """The stored matrix of robot ``name`` as JSON data, if one is stored for ``digest``."""
    path = stored_file(name)
    if not path.is_file():
        return None
    data: dict[str, object] = json.loads(path.read_text(encoding="utf-8"))
    return data if data.get("digest") == digest else None


def write_stored(name: str, digest: str, data: dict[str, object]) -> Path:
    """Store ``data`` (a matrix as JSON data) for robot ``name`` under ``digest``."""
    path = stored_file(name)
    path.parent.mkdir(parents=True, exist_ok=True)
    text = json.dumps({"digest": digest, **data}, indent=1, sort_keys=True)
    path.write_text(text + "\n", encoding="utf-8")
    return path

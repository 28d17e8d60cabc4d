"""URDF files of robot descriptions for pybullet, written once per model content."""

from __future__ import annotations

import hashlib
import os
import tempfile
from pathlib import Path

from robocram.robots import RobotDescription

URDF_CACHE = Path(tempfile.gettempdir()) / "robocram-urdf"


def robot_urdf_file(description: RobotDescription) -> Path:
    """A URDF file of ``description.model`` (frames and boxes added in code included).

    Files are named by content hash, so worlds and copies share them and a changed
    description gets a new file. Written atomically: parallel test workers are safe.
    """
    if description.model is None:
        raise ValueError(
            f"description {description.name!r} is not loaded; pass it through load_description()"
        )
    text = description.model.to_urdf()
    digest = hashlib.sha1(text.encode("utf-8")).hexdigest()[:16]
    path = URDF_CACHE / f"{description.name}-{digest}.urdf"
    if not path.is_file():
        URDF_CACHE.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=URDF_CACHE, suffix=".urdf")
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            out.write(text)
        os.replace(tmp, path)
    return path

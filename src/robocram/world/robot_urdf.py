"""URDF files of robot descriptions for pybullet, written once per model content.

A model with more links than PyBullet holds is written with its fixed links folded into
their parents (:func:`robocram.robots.merge_fixed_links`); the spec keeps their frames.
"""

from __future__ import annotations

import hashlib
import os
import tempfile
from pathlib import Path

from robocram.robots import LoadedDescription, RobotDescription, RobotModel, merge_fixed_links
from robocram.world.body_loading import MAX_LINKS
from robocram.world.body_spec import UrdfSpec
from robocram.world.errors import TooManyLinksError

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
    return model_urdf_file(description.name, description.model)


def model_urdf_file(name: str, model: RobotModel) -> Path:
    """A URDF file of ``model``, named ``name`` and by content hash (see above)."""
    text = model.to_urdf()
    digest = hashlib.sha1(text.encode("utf-8")).hexdigest()[:16]
    path = URDF_CACHE / f"{name}-{digest}.urdf"
    if not path.is_file():
        URDF_CACHE.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=URDF_CACHE, suffix=".urdf")
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            out.write(text)
        os.replace(tmp, path)
    return path


def robot_body_spec(name: str, description: LoadedDescription) -> UrdfSpec:
    """The fixed-base body of a robot; too many links for PyBullet: fixed ones folded."""
    model = description.model
    if len(model.joints) <= MAX_LINKS:
        return UrdfSpec(robot_urdf_file(description), fixed_base=True)
    merged = merge_fixed_links(model)
    if len(merged.model.joints) > MAX_LINKS:
        raise TooManyLinksError(name, str(description.urdf), len(merged.model.joints), MAX_LINKS)
    frames = tuple((frame, host, pose) for frame, (host, pose) in merged.frames.items())
    path = model_urdf_file(f"{description.name}-folded", merged.model)
    return UrdfSpec(path, fixed_base=True, frames=frames)

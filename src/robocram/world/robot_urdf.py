"""The one door for URDFs into PyBullet: every file is read by the checked parser first.

PyBullet's own importer crashes the process on a kinematic loop below the root, ignores
crossed limits and reads every file as UTF-8, so it only ever sees a file that
:class:`robocram.robots.RobotModel` has read: the file itself when it is UTF-8, else the
model written out again. Robot descriptions are written once per model content; a model
with more links than PyBullet holds is written with its fixed links folded into their
parents (:func:`robocram.robots.merge_fixed_links`); the spec keeps their frames.
"""

from __future__ import annotations

import codecs
import dataclasses
import hashlib
import os
import tempfile
import warnings
from pathlib import Path

from robocram.robots import (
    DescriptionError,
    LoadedDescription,
    MissingMeshWarning,
    RobotDescription,
    RobotModel,
    SplitModel,
    merge_fixed_links,
    split_model,
)
from robocram.world.body_spec import UrdfSpec
from robocram.world.errors import BodyLoadError, TooManyLinksError, WorldValueError

URDF_CACHE = Path(tempfile.gettempdir()) / "robocram-urdf"
# Links below the root that PyBullet's joint state queries handle: with 128 (a 129-link
# body) getJointStates fails on every call, so a body holds at most 127.
MAX_LINKS = 127
# PyBullet keeps 128 joint positions per body, 7 of them for the base: a moving joint past
# the 121st is silently not set (measured with chains of 115 to 127 revolute joints).
MAX_MOVING_JOINTS = 121


def robot_urdf_file(description: RobotDescription) -> Path:
    """A URDF file of ``description.model`` (frames and boxes added in code included).

    Files are named by content hash, so worlds and copies share them and a changed
    description gets a new file. Written atomically: parallel test workers are safe.
    """
    if description.model is None:
        raise WorldValueError(
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


def checked_urdf_spec(name: str, spec: UrdfSpec) -> UrdfSpec:
    """``spec`` with a path PyBullet may load, after the URDF parser has read the file.

    Raises:
        BodyLoadError: the file is missing or not a sound URDF (a loop, crossed limits, an
            encoding it does not declare); the message is the parser's, with the line.
        TooManyLinksError: more links below the root than PyBullet holds.
    """
    if spec.checked:
        return spec
    source = str(spec.path)
    if not Path(spec.path).is_file():
        raise BodyLoadError(name, source, f"URDF file {spec.path} does not exist")
    data = Path(spec.path).read_bytes()
    as_is = _utf8(data)
    try:
        with warnings.catch_warnings():
            if as_is:  # PyBullet gets the file itself, not the boxes standing in for meshes
                warnings.simplefilter("ignore", MissingMeshWarning)
            model = RobotModel.from_file(spec.path)
    except DescriptionError as err:
        raise BodyLoadError(name, source, str(err)) from err
    except RecursionError as err:
        raise BodyLoadError(name, source, "its XML is nested too deeply to read") from err
    if _fits(model):
        path = spec.path if as_is else model_urdf_file(model.name, model)
        return dataclasses.replace(spec, path=path, checked=True, model=model)
    return _split_spec(name, source, spec, model)


def _fits(model: RobotModel) -> bool:
    return len(model.joints) <= MAX_LINKS and len(model.movable_joints()) <= MAX_MOVING_JOINTS


def check_loadable(name: str, source: str, model: RobotModel) -> SplitModel:
    """``model`` as the fixed bodies it loads as: one if it fits, else cut at subtrees
    rigid with its root (``robots/model_split.py``).

    Raises:
        TooManyLinksError: even cut, its root part holds too many links or moving joints.
    """
    split = split_model(model, MAX_LINKS, MAX_MOVING_JOINTS)
    hint = "no more subtree hung on fixed joints from the root could be cut off into a body"
    check_link_count(name, source, split.main, hint if split.parts else "")
    return split


def _split_spec(name: str, source: str, spec: UrdfSpec, model: RobotModel) -> UrdfSpec:
    """``spec`` as several fixed bodies, cut at subtrees rigid with the root."""
    if not spec.fixed_base:
        check_link_count(name, source, model, "load it with a fixed base to cut it in parts")
    split = check_loadable(name, source, model)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)
        main = model_urdf_file(split.main.name, split.main)
        parts = tuple(
            (model_urdf_file(part.model.name, part.model), part.root_T_base) for part in split.parts
        )
    return dataclasses.replace(spec, path=main, checked=True, parts=parts, model=model)


def check_link_count(name: str, source: str, model: RobotModel, hint: str = "") -> None:
    """Refuse a model with more links or moving joints than PyBullet holds."""
    if len(model.joints) > MAX_LINKS:
        raise TooManyLinksError(name, source, len(model.joints), MAX_LINKS, hint=hint)
    moving = len(model.movable_joints())
    if moving > MAX_MOVING_JOINTS:
        raise TooManyLinksError(name, source, moving, MAX_MOVING_JOINTS, "moving joints", hint=hint)


def _utf8(data: bytes) -> bool:
    """Whether PyBullet's importer, which reads UTF-8 only, reads ``data`` as it is meant."""
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        return False
    try:
        data.decode("utf-8")
    except UnicodeDecodeError:
        return False
    return True


def robot_body_spec(name: str, description: LoadedDescription) -> UrdfSpec:
    """The fixed-base body of a robot; too many links for PyBullet: fixed ones folded."""
    model = description.model
    if len(model.joints) <= MAX_LINKS:
        check_link_count(name, str(description.urdf), model)
        return UrdfSpec(robot_urdf_file(description), fixed_base=True, checked=True)
    merged = merge_fixed_links(model)
    check_link_count(name, str(description.urdf), merged.model)
    frames = tuple((frame, host, pose) for frame, (host, pose) in merged.frames.items())
    path = model_urdf_file(f"{description.name}-folded", merged.model)
    return UrdfSpec(path, fixed_base=True, frames=frames, checked=True)

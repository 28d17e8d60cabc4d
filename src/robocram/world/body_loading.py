"""Making a body from its spec, checked: failures are typed and leave nothing behind.

A URDF passes the checked parser first (:func:`checked_urdf_spec`). PyBullet answers joint
state queries only for bodies of at most :data:`MAX_LINKS` links below the root; a bigger
fixed-base model is cut into several bodies there (``UrdfSpec.parts``), a bigger body of
any other kind is refused.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from robocram.tf import Pose
from robocram.world.body_spec import BodySpec, MeshSpec, UrdfSpec
from robocram.world.errors import BodyLoadError, TooManyLinksError
from robocram.world.pybullet_backend import pybullet
from robocram.world.robot_urdf import MAX_LINKS, checked_urdf_spec

if TYPE_CHECKING:
    from robocram.robots import RobotModel


@dataclass(frozen=True)
class LoadedBodies:
    """The bodies one spec made: the root part first, and where each part's base link
    lies in the root link's frame (the first: the identity)."""

    bodies: tuple[int, ...]
    offsets: tuple[Pose, ...]
    model: RobotModel | None = None  # the parsed URDF (checked before PyBullet read it)


def create_body(name: str, spec: BodySpec, cid: int) -> LoadedBodies:
    """The bodies of ``spec`` called ``name``; a failed or oversized load leaves none."""
    source = str(spec.path) if isinstance(spec, UrdfSpec | MeshSpec) else "a shape"
    parts: tuple[tuple[UrdfSpec, Pose], ...] = ()
    if isinstance(spec, UrdfSpec):
        spec = checked_urdf_spec(name, spec)
        parts = tuple(
            (UrdfSpec(path, fixed_base=True, scale=spec.scale, checked=True), where)
            for path, where in spec.parts
        )
    made: list[int] = []
    try:
        for part in (spec, *(p for p, _ in parts)):
            made.append(_one_body(name, source, part, cid))
    except BodyLoadError:
        for body in made:
            pybullet.removeBody(body, physicsClientId=cid)
        raise
    scale = spec.scale if isinstance(spec, UrdfSpec) else 1.0
    offsets = tuple(_scaled(where, scale) for _, where in parts)
    model = spec.model if isinstance(spec, UrdfSpec) else None
    return LoadedBodies(tuple(made), (Pose(), *offsets), model)


def _one_body(name: str, source: str, spec: BodySpec, cid: int) -> int:
    try:
        body = spec.create(cid)
    except (pybullet.error, FileNotFoundError) as err:
        raise BodyLoadError(name, source, str(err).strip() or "PyBullet failed") from err
    joints = pybullet.getNumJoints(body, physicsClientId=cid)
    if joints > MAX_LINKS:
        pybullet.removeBody(body, physicsClientId=cid)
        raise TooManyLinksError(name, source, joints, MAX_LINKS)
    return body


def _scaled(pose: Pose, scale: float) -> Pose:
    x, y, z = pose.position
    return Pose((x * scale, y * scale, z * scale), pose.orientation)

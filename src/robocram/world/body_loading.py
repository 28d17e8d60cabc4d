"""Making a body from its spec, checked: failures are typed and leave nothing behind.

A URDF passes the checked parser first (:func:`checked_urdf_spec`). PyBullet answers joint
state queries only for bodies of at most :data:`MAX_LINKS` links below the root; a bigger
body loads but then fails on every query, so it is refused.
"""

from __future__ import annotations

from robocram.world.body_spec import BodySpec, MeshSpec, UrdfSpec
from robocram.world.errors import BodyLoadError, TooManyLinksError
from robocram.world.pybullet_backend import pybullet
from robocram.world.robot_urdf import MAX_LINKS, checked_urdf_spec


def create_body(name: str, spec: BodySpec, cid: int) -> int:
    """The body of ``spec`` called ``name``; a failed or oversized load leaves no body."""
    source = str(spec.path) if isinstance(spec, UrdfSpec | MeshSpec) else "a shape"
    if isinstance(spec, UrdfSpec):
        spec = checked_urdf_spec(name, spec)
    try:
        body = spec.create(cid)
    except (pybullet.error, FileNotFoundError) as err:
        raise BodyLoadError(name, source, str(err).strip() or "PyBullet failed") from err
    joints = pybullet.getNumJoints(body, physicsClientId=cid)
    if joints > MAX_LINKS:
        pybullet.removeBody(body, physicsClientId=cid)
        raise TooManyLinksError(name, source, joints, MAX_LINKS)
    return body

"""Spheres that bound where a moving geometry can go, to leave out far static geometry.

A geometry hangs below its topmost planned joint (the anchor); whatever the joint values,
it stays within the sum of the joint offsets below the anchor, the travel of prismatic
joints and its own size from the anchor's origin. A static shape whose bounding sphere
misses that sphere can never be touched, so the scene never tests it.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics.robot_kinematics import RobotKinematics
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import coal
    import pinocchio as pin
else:
    coal = LazyLibrary("coal")
    pin = LazyLibrary("pinocchio")


@dataclass(frozen=True)
class Sphere:
    """A ball of ``radius`` [m] around ``centre`` (robot root frame)."""

    centre: NDArray[np.float64]
    radius: float

    def overlaps(self, other: Sphere) -> bool:
        """Whether the balls meet."""
        if math.isinf(self.radius) or math.isinf(other.radius):
            return True
        return float(np.linalg.norm(self.centre - other.centre)) <= self.radius + other.radius


@dataclass(frozen=True)
class Spheres:
    """Balls as arrays, so that one ball is tested against all of them at once."""

    centres: NDArray[np.float64]  # (balls, 3)
    radii: NDArray[np.float64]  # (balls,)

    @classmethod
    def of(cls, spheres: Collection[Sphere]) -> Spheres:
        """The balls of ``spheres``."""
        centres = np.array([s.centre for s in spheres], dtype=float).reshape(-1, 3)
        return cls(centres, np.array([s.radius for s in spheres], dtype=float))

    def meet(self, other: Sphere) -> bool:
        """Whether any of the balls meets ``other`` (as :meth:`Sphere.overlaps`)."""
        if math.isinf(other.radius):
            return bool(len(self.radii))
        gaps = np.linalg.norm(self.centres - other.centre, axis=1)
        return bool(np.any(np.isinf(self.radii) | (gaps <= self.radii + other.radius)))

    def meet_each(self, others: Sequence[Sphere]) -> list[bool]:
        """:meth:`meet` of each of ``others``, on arrays (the same operations per ball,
        so the same answers)."""
        if not others:
            return []
        centres = np.array([o.centre for o in others], dtype=float).reshape(-1, 3)
        radii = np.array([o.radius for o in others], dtype=float)
        gaps = np.linalg.norm(self.centres[None, :, :] - centres[:, None, :], axis=2)
        met = (np.isinf(self.radii)[None, :] | (gaps <= self.radii[None, :] + radii[:, None])).any(
            axis=1
        )
        met[np.isinf(radii)] = bool(len(self.radii))
        return [bool(m) for m in met]


def shape_sphere(geometry: coal.CollisionGeometry, placement: pin.SE3) -> Sphere:
    """The ball around a geometry's local bounding box, at ``placement``."""
    if isinstance(geometry, coal.Halfspace):
        return Sphere(np.zeros(3), math.inf)
    geometry.computeLocalAABB()
    centre = placement.act(np.asarray(geometry.aabb_center, dtype=float))
    return Sphere(np.asarray(centre, dtype=float), float(geometry.aabb_radius))


def reach_sphere(
    kin: RobotKinematics,
    data: pin.Data,
    obj: pin.GeometryObject,
    active: Collection[str],
    margin: float,
) -> Sphere:
    """Where ``obj`` can be for any values of the ``active`` joints (``data`` holds FK at the
    snapshot); grown by ``margin`` [m]."""
    model = kin.model
    path = []
    joint = int(obj.parentJoint)
    while joint > 0:
        path.append(joint)
        joint = int(model.parents[joint])
    anchors = [j for j in path if model.names[j] in active]
    if not anchors:  # never moves: a point ball at its place
        return _grown(shape_sphere(obj.geometry, data.oMi[obj.parentJoint] * obj.placement), margin)
    anchor = anchors[-1]  # the topmost
    radius = _travel(kin, anchor, data, below=False)
    for j in path[: path.index(anchor)]:
        radius += float(np.linalg.norm(model.jointPlacements[j].translation))
        radius += _travel(kin, j, data, below=True)
    local = shape_sphere(obj.geometry, obj.placement)
    radius += float(np.linalg.norm(local.centre)) + local.radius
    return Sphere(np.asarray(data.oMi[anchor].translation, dtype=float), radius + margin)


def _travel(kin: RobotKinematics, joint: int, data: pin.Data, below: bool) -> float:
    """How far a prismatic joint moves its child frame [m] (0 for revolute joints)."""
    name = kin.model.names[joint]
    spec = kin.robot_model.joints[name]
    if spec.type != "prismatic":
        return 0.0
    info = kin.joints[name]
    if below:
        return max(abs(info.lower), abs(info.upper))
    # the anchor's frame is at its snapshot value; it moves by at most this from there
    return 2.0 * max(abs(info.lower), abs(info.upper))


def _grown(sphere: Sphere, margin: float) -> Sphere:
    return Sphere(sphere.centre, sphere.radius + margin)

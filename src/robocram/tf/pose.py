"""Rigid poses: a position [m] and an orientation quaternion ``(x, y, z, w)``.

A :class:`Pose` is frame-less (the caller knows the frame, usually ``map``);
:class:`~robocram.tf.stamped.PoseStamped` adds the frame and a time stamp.
Composition reads like frames: ``pose_in_map = transform_base_to_map * pose_in_base``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Union

import numpy as np
from numpy.typing import NDArray

from robocram.tf import quaternion as quat
from robocram.tf.errors import PoseValueError, TfUsageError

Vector3 = tuple[float, float, float]
PoseLike = Union["Pose", Sequence[float], tuple[Sequence[float], Sequence[float]]]


def _vector3(v: Sequence[float], what: str) -> Vector3:
    if len(v) != 3:
        raise PoseValueError(f"{what} needs 3 components (x, y, z) [m], got {len(v)}: {v!r}")
    x, y, z = float(v[0]), float(v[1]), float(v[2])
    if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(z)):  # poses are hot
        raise PoseValueError(f"{what} {v!r} has a non-finite component")
    return (x, y, z)


@dataclass(frozen=True)
class Pose:
    """A position [m] and a unit orientation quaternion (x, y, z, w).

    >>> Pose((1, 2, 3)).position
    (1.0, 2.0, 3.0)
    >>> (Pose((1, 0, 0)) * Pose((0, 1, 0))).position
    (1.0, 1.0, 0.0)
    """

    position: Vector3 = (0.0, 0.0, 0.0)
    orientation: quat.Quaternion = quat.IDENTITY

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", _vector3(self.position, "position"))
        object.__setattr__(self, "orientation", quat.normalized(self.orientation))

    @classmethod
    def coerce(cls, value: PoseLike) -> Pose:
        """Accept a Pose, ``(x, y, z)`` or ``((x, y, z), (qx, qy, qz, qw))``."""
        if isinstance(value, Pose):
            return value
        pose = getattr(value, "pose", None)  # a PoseStamped or similar carries one
        if isinstance(pose, Pose):
            return pose
        if isinstance(value, Sequence) and len(value) == 2:
            pos, ori = value
            if isinstance(pos, Sequence) and isinstance(ori, Sequence):
                return cls(tuple(pos), tuple(ori))  # type: ignore[arg-type]
        if isinstance(value, Sequence) and len(value) == 3:
            return cls(tuple(value))  # type: ignore[arg-type]
        raise TfUsageError(
            f"cannot read a pose from {value!r}; give Pose((x, y, z), (qx, qy, qz, qw)), "
            "(x, y, z) or ((x, y, z), (qx, qy, qz, qw))"
        )

    @classmethod
    def from_xyz_rpy(cls, xyz: Sequence[float], rpy: Sequence[float] = (0, 0, 0)) -> Pose:
        """Pose from a position [m] and fixed-axis roll, pitch, yaw [rad]."""
        return cls(_vector3(xyz, "xyz"), quat.from_euler(*_vector3(rpy, "rpy")))

    @classmethod
    def from_matrix(cls, m: NDArray[np.float64]) -> Pose:
        """Pose of a 4 x 4 homogeneous transform."""
        return cls(tuple(float(c) for c in m[:3, 3]), quat.from_matrix(m[:3, :3]))  # type: ignore[arg-type]

    def matrix(self) -> NDArray[np.float64]:
        """4 x 4 homogeneous transform of this pose."""
        m = np.eye(4)
        m[:3, :3] = quat.to_matrix(self.orientation)
        m[:3, 3] = self.position
        return m

    def __mul__(self, other: Pose) -> Pose:
        """Compose: ``self`` applied after ``other`` (``a_T_b * b_T_c = a_T_c``)."""
        p = quat.rotate(self.orientation, other.position)
        pos = (p[0] + self.position[0], p[1] + self.position[1], p[2] + self.position[2])
        return Pose(pos, quat.multiply(self.orientation, other.orientation))

    def inverse(self) -> Pose:
        """The pose ``p`` with ``self * p`` the identity."""
        q = quat.conjugate(self.orientation)
        p = quat.rotate(q, self.position)
        return Pose((-p[0], -p[1], -p[2]), q)

    def transform_point(self, point: Sequence[float]) -> Vector3:
        """Map a point given in this pose's frame into the parent frame."""
        r = quat.rotate(self.orientation, _vector3(point, "point"))
        return (r[0] + self.position[0], r[1] + self.position[1], r[2] + self.position[2])

    def rpy(self) -> Vector3:
        """Roll, pitch, yaw [rad] of the orientation."""
        return quat.to_euler(self.orientation)

    def distance_to(self, other: Pose) -> float:
        """Euclidean distance [m] between the two positions."""
        return math.dist(self.position, other.position)

    def angle_to(self, other: Pose) -> float:
        """Rotation angle [rad] between the two orientations."""
        return quat.angle_between(self.orientation, other.orientation)

    def as_tuple(self) -> tuple[Vector3, quat.Quaternion]:
        """``((x, y, z), (qx, qy, qz, qw))``, the shape pybullet takes."""
        return (self.position, self.orientation)

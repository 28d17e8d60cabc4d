"""Stamped poses and transforms: a pose plus the frame it is given in and a time stamp.

The shapes follow ROS's ``geometry_msgs/PoseStamped`` and ``TransformStamped``: a
:class:`PoseStamped` in ``frame_id`` is the pose ``frame_id_T_pose``; a
:class:`TransformStamped` from ``frame_id`` to ``child_frame_id`` is ``frame_id_T_child``,
i.e. the pose of the child frame expressed in the parent frame. Stamps are seconds.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from robocram.tf import quaternion as quat
from robocram.tf.errors import TfArgumentError
from robocram.tf.pose import Pose, PoseLike, Vector3, _vector3


def _frame_name(name: str, what: str) -> str:
    if not isinstance(name, str) or not name:
        raise TfArgumentError(f"{what} must be a non-empty frame name, got {name!r}")
    return name


def _stamp(stamp: float) -> float:
    value = float(stamp)
    if not math.isfinite(value):
        raise TfArgumentError(f"stamp must be a finite time [s], got {stamp!r}")
    return value


@dataclass(frozen=True)
class PoseStamped:
    """A pose in frame ``frame_id`` at time ``stamp`` [s].

    >>> PoseStamped("map", (1.5, 0, 1)).position
    (1.5, 0.0, 1.0)
    >>> Pose.coerce(PoseStamped("map", (1, 2, 3))).position
    (1.0, 2.0, 3.0)
    """

    frame_id: str
    position: Vector3 = (0.0, 0.0, 0.0)  # [m]
    orientation: quat.Quaternion = quat.IDENTITY  # (x, y, z, w)
    stamp: float = 0.0  # [s]

    def __post_init__(self) -> None:
        object.__setattr__(self, "frame_id", _frame_name(self.frame_id, "frame_id"))
        object.__setattr__(self, "position", _vector3(self.position, "position"))
        object.__setattr__(self, "orientation", quat.normalized(self.orientation))
        object.__setattr__(self, "stamp", _stamp(self.stamp))

    @classmethod
    def from_pose(cls, frame_id: str, pose: PoseLike, stamp: float = 0.0) -> PoseStamped:
        """Stamp ``pose`` (anything :meth:`Pose.coerce` reads) with a frame and a time [s]."""
        p = Pose.coerce(pose)
        return cls(frame_id, p.position, p.orientation, stamp)

    @property
    def pose(self) -> Pose:
        """The frame-less pose (``frame_id_T_pose``)."""
        return Pose(self.position, self.orientation)

    def with_frame(self, frame_id: str, pose: PoseLike | None = None) -> PoseStamped:
        """Copy with another frame name and, if given, another pose; the stamp is kept."""
        p = self.pose if pose is None else Pose.coerce(pose)
        return PoseStamped(frame_id, p.position, p.orientation, self.stamp)

    def with_stamp(self, stamp: float) -> PoseStamped:
        """Copy with another time stamp [s]."""
        return PoseStamped(self.frame_id, self.position, self.orientation, stamp)


@dataclass(frozen=True)
class TransformStamped:
    """The transform ``frame_id_T_child_frame_id`` at time ``stamp`` [s].

    ``translation`` [m] and ``rotation`` (x, y, z, w) place the child frame in the parent.

    >>> t = TransformStamped("map", "base_footprint", (1, 0, 0))
    >>> t.pose.position
    (1.0, 0.0, 0.0)
    """

    frame_id: str
    child_frame_id: str
    translation: Vector3 = (0.0, 0.0, 0.0)  # [m]
    rotation: quat.Quaternion = quat.IDENTITY  # (x, y, z, w)
    stamp: float = 0.0  # [s]

    def __post_init__(self) -> None:
        object.__setattr__(self, "frame_id", _frame_name(self.frame_id, "frame_id"))
        object.__setattr__(
            self, "child_frame_id", _frame_name(self.child_frame_id, "child_frame_id")
        )
        if self.frame_id == self.child_frame_id:
            raise TfArgumentError(f"a transform from {self.frame_id!r} to itself is meaningless")
        object.__setattr__(self, "translation", _vector3(self.translation, "translation"))
        object.__setattr__(self, "rotation", quat.normalized(self.rotation))
        object.__setattr__(self, "stamp", _stamp(self.stamp))

    @classmethod
    def from_pose(
        cls, frame_id: str, child_frame_id: str, pose: PoseLike, stamp: float = 0.0
    ) -> TransformStamped:
        """Transform placing ``child_frame_id`` at ``pose`` given in ``frame_id``."""
        p = Pose.coerce(pose)
        return cls(frame_id, child_frame_id, p.position, p.orientation, stamp)

    @property
    def pose(self) -> Pose:
        """The child frame's pose in the parent frame (``frame_id_T_child``)."""
        return Pose(self.translation, self.rotation)

    def as_pose(self) -> Pose:
        """Same as :attr:`pose`, as a method for callers used to tf2's ``as_pose``."""
        return self.pose

    def inverse(self) -> TransformStamped:
        """The transform ``child_T_frame_id`` (parent and child swapped)."""
        inv = self.pose.inverse()
        return TransformStamped(
            self.child_frame_id, self.frame_id, inv.position, inv.orientation, self.stamp
        )

"""A robot's links as coal geometry on pinocchio's joints, built once per robot model.

Each collision shape of a link (a mesh as PyBullet's convex hulls, see
:mod:`~robocram.motion.coal_shapes`) becomes a :class:`Part` hanging from the pinocchio
joint that moves the link, with its bounding ball in that joint's frame. The clearance
model (:mod:`~robocram.motion.coal_clearance`) places the parts it needs per check.
"""

from __future__ import annotations

import dataclasses
import threading
from collections.abc import Collection
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from robocram.kinematics.robot_kinematics import RobotKinematics, pose_to_se3, robot_kinematics
from robocram.motion.coal_shapes import coal_geometries
from robocram.motion.joint_trajectory import FloatArray
from robocram.robots import RobotModel
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import coal
    import pinocchio as pin
else:
    coal = LazyLibrary("coal")
    pin = LazyLibrary("pinocchio")


@dataclass(frozen=True)
class Part:
    """One convex piece of geometry riding on a pinocchio joint."""

    label: str  # the robot link, or the held object, it belongs to
    joint: int  # the pinocchio joint it moves with (0: the root)
    placement: pin.SE3  # joint frame -> geometry frame
    geometry: coal.CollisionGeometry
    centre: FloatArray  # [m] of its bounding ball, in the joint's frame
    radius: float  # [m] of its bounding ball
    extent: float  # [m] the farthest its ball reaches from the joint's origin
    axes: FloatArray  # (3, 3) its bounding box's axes in the joint's frame
    halves: FloatArray  # [m] (3,) its bounding box's half extents


def part(label: str, joint: int, placement: pin.SE3, geometry: coal.CollisionGeometry) -> Part:
    """A part with its bounding ball (around the geometry's local bounding box)."""
    geometry.computeLocalAABB()
    centre = np.asarray(placement.act(np.asarray(geometry.aabb_center, dtype=float)), float)
    radius = float(geometry.aabb_radius)
    box = geometry.aabb_local
    halves = (np.asarray(box.max_, dtype=float) - np.asarray(box.min_, dtype=float)) / 2.0
    axes = np.asarray(placement.rotation, dtype=float)
    return Part(
        label, joint, placement, geometry, centre, radius, _norm(centre) + radius, axes, halves
    )


def _norm(vector: FloatArray) -> float:
    return float(np.sqrt(vector @ vector))


@dataclass
class RobotGeometry:
    """Every link's parts, by link; and, per set of planned joints, how far each joint's
    parts can get from the topmost planned joint above it (for leaving far geometry out)."""

    kinematics: RobotKinematics
    parts: dict[str, tuple[Part, ...]]
    _chains: dict[tuple[int, frozenset[str]], tuple[int, float]] = field(default_factory=dict)
    _frames: dict[str, tuple[int, FloatArray]] = field(default_factory=dict)
    _named: dict[tuple[tuple[str, str], ...], tuple[Part, ...]] = field(default_factory=dict)
    _local: threading.local = field(default_factory=threading.local)

    def data(self) -> pin.Data:
        """This thread's pinocchio data for the model (making one costs ~0.4 ms, more
        than a motion's checks): valid only until the next forward kinematics on it."""
        found: pin.Data | None = getattr(self._local, "data", None)
        if found is None:
            found = self._local.data = self.kinematics.model.createData()
        return found

    def frame(self, link: str) -> tuple[int, FloatArray]:
        """The pinocchio joint ``link``'s frame rides on, and the frame in the joint's (4x4)."""
        found = self._frames.get(link)
        if found is None:
            kin = self.kinematics
            frame = kin.model.frames[kin.frame_id(link)]
            found = self._frames[link] = (int(frame.parentJoint), frame.placement.homogeneous)
        return found

    def named_parts(self, names: tuple[tuple[str, str], ...]) -> tuple[Part, ...]:
        """The parts of the links in ``names`` (link, label), labelled as given."""
        found = self._named.get(names)
        if found is None:
            found = self._named[names] = tuple(
                dataclasses.replace(p, label=label)
                for link, label in names
                for p in self.parts.get(link, ())
            )
        return found

    @classmethod
    def of(cls, model: RobotModel) -> RobotGeometry:
        """The geometry of ``model`` (kept with it: ``model.derived(RobotGeometry.of)``)."""
        kin = robot_kinematics(model)
        parts: dict[str, tuple[Part, ...]] = {}
        for link in model.links.values():
            frame = kin.model.frames[kin.frame_id(link.name)]
            found = []
            for collision in link.collisions:
                shape = collision.geometry
                extents = shape.scale if shape.kind == "mesh" else shape.extents()
                placement = frame.placement * pose_to_se3(collision.origin)
                for piece in coal_geometries(
                    shape.kind, extents or (1.0, 1.0, 1.0), shape.filename
                ):
                    found.append(part(link.name, int(frame.parentJoint), placement, piece))
            if found:
                parts[link.name] = tuple(found)
        return cls(kin, parts)

    def anchor(self, joint: int, planned: Collection[str]) -> tuple[int, float]:
        """The topmost planned joint above ``joint`` (``joint`` itself if none is) and the
        most [m] ``joint``'s frame can be from it, whatever the planned joints' values."""
        key = (joint, frozenset(planned))
        found = self._chains.get(key)
        if found is None:
            found = self._chains[key] = self._anchor(joint, key[1])
        return found

    def _anchor(self, joint: int, planned: frozenset[str]) -> tuple[int, float]:
        model = self.kinematics.model
        path = []
        j = joint
        while j > 0:
            path.append(j)
            j = int(model.parents[j])
        anchors = [j for j in path if model.names[j] in planned]
        if not anchors:
            return joint, 0.0
        anchor = anchors[-1]
        reach = _slide(self.kinematics, anchor, 2.0)  # the anchor moves from where it is
        for j in path[: path.index(anchor)]:
            reach += float(np.linalg.norm(model.jointPlacements[j].translation))
            reach += _slide(self.kinematics, j, 1.0)
        return anchor, reach


def _slide(kin: RobotKinematics, joint: int, factor: float) -> float:
    """``factor`` times a prismatic joint's largest value [m] (0 for other joints)."""
    name = kin.model.names[joint]
    if kin.robot_model.joints[name].type != "prismatic":
        return 0.0
    info = kin.joints[name]
    return factor * max(abs(info.lower), abs(info.upper))

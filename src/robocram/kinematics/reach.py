"""How far an arm can reach: a bound that rules targets out before any descent.

Every joint keeps the distance between its origin and the next joint's origin fixed
(revolute and continuous joints turn about their origin), except prismatic joints, which
add at most their longest travel. So the tool frame stays within ``radius`` of the first
moving joint, the sum of those lengths; when that first joint is prismatic (a torso), within
``radius`` of the segment it slides along. A target farther away is certainly unreachable;
one inside may still be unreachable (orientation, limits), which only IK can tell.

The same holds for the *wrist*: the origin of the last joint whose place in the tool
frame no joint after it changes (the wrist joints of a spherical wrist turn about axes
through it). A target fixes where the wrist must be, and that point must lie within the
shorter ``wrist_radius``: this rules out tool orientations the arm cannot take there (a
top grasp beyond the shoulder's reach minus the hand), which the tool's bound lets pass.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from robocram.kinematics.arm_chain import ArmChain, FloatArray
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

_ON_AXIS = 1e-9  # [m] an offset closer than this to a joint's axis lies on it
# a wrist this near its bound is not ruled out, so that a query that fails still answers
# with the nearest configuration it finds for a target a near miss from reach
NEAR_MISS_POSITION = 0.01  # [m]
NEAR_MISS_ORIENTATION = 0.05  # [rad]


def _travel(chain: ArmChain, row: int) -> float:
    """Longest distance a prismatic path joint moves its child's origin [m]; 0 if revolute."""
    name = chain.path[row]
    if chain.kin.robot_model.joints[name].type != "prismatic":
        return 0.0
    info = chain.kin.joints[name]
    return max(abs(info.lower), abs(info.upper))


def _wrist_row(chain: ArmChain) -> int:
    """The first path row from which on every joint turns about an axis through the
    previous joint's origin, so that row's origin is fixed in the tool frame."""
    row = len(chain.path) - 1
    while row > chain.first_row:
        joint = chain.kin.robot_model.joints[chain.path[row]]
        if joint.type == "prismatic":
            break
        placement = chain.model.jointPlacements[row + 1]
        back = placement.rotation.T @ placement.translation  # parent origin, this joint's frame
        axis = np.asarray(joint.axis, float) / np.linalg.norm(joint.axis)
        if np.linalg.norm(np.cross(axis, back)) > _ON_AXIS:
            break
        row -= 1
    return row


def _wrist_in_tool(chain: ArmChain, row: int) -> FloatArray:
    """The origin of path row ``row`` in the tool frame (the same at every configuration)."""
    data = chain.model.createData()
    pin.framesForwardKinematics(chain.model, data, pin.neutral(chain.model))
    return np.asarray(data.oMf[chain.frame_id].actInv(data.oMi[row + 1]).translation, float)


@dataclass(frozen=True)
class ReachBound:
    """The ball (or capsule, for a leading prismatic joint) the tool frame stays in, and
    the smaller one the wrist stays in.

    ``start`` and ``end`` are the ends of the segment the first moving joint's origin
    can be on, in the chain base frame (equal unless that joint is prismatic).
    """

    start: FloatArray  # [m] in the chain base
    end: FloatArray  # [m]
    radius: float  # [m]
    wrist: FloatArray  # [m] the wrist in the tool frame
    wrist_radius: float  # [m]

    @classmethod
    def of(cls, chain: ArmChain) -> ReachBound:
        """The bound of ``chain`` from its URDF lengths and prismatic limits."""
        first = chain.first_row
        placement = chain.model.jointPlacements[first + 1]
        start = end = np.asarray(placement.translation, float)
        radius = 0.0
        if chain.kin.robot_model.joints[chain.path[first]].type == "prismatic":
            info = chain.kin.joints[chain.path[first]]
            axis = np.asarray(chain.kin.robot_model.joints[chain.path[first]].axis, float)
            axis = placement.rotation @ (axis / np.linalg.norm(axis))
            start, end = start + info.lower * axis, start + info.upper * axis
        else:
            radius += _travel(chain, first)
        wrist_row = _wrist_row(chain)
        wrist_radius = radius
        for row in range(first + 1, len(chain.path)):
            radius += float(np.linalg.norm(chain.model.jointPlacements[row + 1].translation))
            radius += _travel(chain, row)
            if row == wrist_row:
                wrist_radius = radius
        radius += float(np.linalg.norm(chain.model.frames[chain.frame_id].placement.translation))
        return cls(start, end, radius, _wrist_in_tool(chain, wrist_row), wrist_radius)

    def distance_outside(self, position_in_base: FloatArray) -> float:
        """How far [m] a tool position (chain base frame) lies beyond the bound; <= 0 inside."""
        return self._outside(position_in_base.tolist(), self.radius)

    def pose_outside(self, target_in_base: pin.SE3) -> float:
        """How far [m] the tool or the wrist at a target (chain base frame) lies beyond its
        bound, whichever is farther; <= 0 when both are inside."""
        wrist = target_in_base.act(self.wrist).tolist()
        return max(
            self.distance_outside(target_in_base.translation),
            self._outside(wrist, self.wrist_radius),
        )

    def excludes(
        self, target_in_base: pin.SE3, tolerance: float, orientation_tolerance: float = 0.0
    ) -> bool:
        """Whether a target is farther than the bound plus ``tolerance`` [m], or its wrist
        farther than a near miss (or the tolerances, if larger) moves it."""
        if self.distance_outside(target_in_base.translation) > tolerance:
            return True
        position = max(tolerance, NEAR_MISS_POSITION)
        turn = max(orientation_tolerance, NEAR_MISS_ORIENTATION)
        slack = position + float(np.linalg.norm(self.wrist)) * turn
        return self._outside(target_in_base.act(self.wrist).tolist(), self.wrist_radius) > slack

    def _outside(self, p: list[float], radius: float) -> float:
        """How far [m] point ``p`` lies beyond ``radius`` of the start-end segment."""
        a, b = self.start.tolist(), self.end.tolist()
        span = [e - s for s, e in zip(a, b, strict=True)]
        length2 = sum(d * d for d in span)
        t = 0.0
        if length2 > 0.0:
            along = sum((q - s) * d for q, s, d in zip(p, a, span, strict=True)) / length2
            t = min(max(along, 0.0), 1.0)
        closest = [s + t * d for s, d in zip(a, span, strict=True)]
        return math.dist(p, closest) - radius

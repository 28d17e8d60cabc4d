"""How far an arm can reach: a bound that rules targets out before any descent.

Every joint keeps the distance between its origin and the next joint's origin fixed
(revolute and continuous joints turn about their origin), except prismatic joints, which
add at most their longest travel. So the tool frame stays within ``radius`` of the first
moving joint, the sum of those lengths; when that first joint is prismatic (a torso), within
``radius`` of the segment it slides along. A target farther away is certainly unreachable;
one inside may still be unreachable (orientation, limits), which only IK can tell.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from robocram.kinematics.arm_chain import ArmChain, FloatArray


def _travel(chain: ArmChain, row: int) -> float:
    """Longest distance a prismatic path joint moves its child's origin [m]; 0 if revolute."""
    name = chain.path[row]
    if chain.kin.robot_model.joints[name].type != "prismatic":
        return 0.0
    info = chain.kin.joints[name]
    return max(abs(info.lower), abs(info.upper))


@dataclass(frozen=True)
class ReachBound:
    """The ball (or capsule, for a leading prismatic joint) the tool frame stays in.

    ``start`` and ``end`` are the ends of the segment the first moving joint's origin
    can be on, in the chain base frame (equal unless that joint is prismatic).
    """

    start: FloatArray  # [m] in the chain base
    end: FloatArray  # [m]
    radius: float  # [m]

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
        for row in range(first + 1, len(chain.path)):
            radius += float(np.linalg.norm(chain.model.jointPlacements[row + 1].translation))
            radius += _travel(chain, row)
        radius += float(np.linalg.norm(chain.model.frames[chain.frame_id].placement.translation))
        return cls(start, end, radius)

    def distance_outside(self, position_in_base: FloatArray) -> float:
        """How far [m] a tool position (chain base frame) lies beyond the bound; <= 0 inside."""
        p, a, b = position_in_base.tolist(), self.start.tolist(), self.end.tolist()
        span = [e - s for s, e in zip(a, b, strict=True)]
        length2 = sum(d * d for d in span)
        t = 0.0
        if length2 > 0.0:
            along = sum((q - s) * d for q, s, d in zip(p, a, span, strict=True)) / length2
            t = min(max(along, 0.0), 1.0)
        closest = [s + t * d for s, d in zip(a, span, strict=True)]
        return math.dist(p, closest) - self.radius

    def excludes(self, target_in_base: pin.SE3, tolerance: float) -> bool:
        """Whether a target is farther than the bound plus ``tolerance`` [m]."""
        return self.distance_outside(target_in_base.translation) > tolerance

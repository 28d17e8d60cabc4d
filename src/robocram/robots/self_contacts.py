"""Which links of a robot meet in a configuration, on their collision shapes, without physics.

The draft has no world to ask (only ``robocram.world`` runs PyBullet), so it checks a
pose it proposes through pinocchio's geometry (coal underneath), meshes as their convex
hulls as PyBullet collides them (a concave torso's hull reaches far past its mesh), as
MoveIt's setup
assistant does before it writes an SRDF: pairs of links joined by one joint (fixed
joints merged), and pairs that already meet with every joint at zero (within limits),
are left out; every other pair counts.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from robocram.robots.lazy_library import LazyLibrary
from robocram.robots.mimic import mimic_followers
from robocram.robots.robot_model import RobotModel

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

CLEARANCE = 0.01  # [m] links nearer than this on their meshes meet: a pose checked here is
# checked again on PyBullet's convex hulls, which reach past the meshes (a Fetch's parked
# finger 2.8 mm from its shoulder on the hulls), and a motion must reach it without touching


class SelfContacts:
    """The robot's collision meshes and the pairs that count (see the module docstring)."""

    def __init__(self, model: RobotModel) -> None:
        self.model = model
        text = model.to_urdf()
        self.kinematics = pin.buildModelFromXML(text)
        self.geometry = pin.buildGeomFromUrdfString(self.kinematics, text, pin.COLLISION)
        for item in self.geometry.geometryObjects:  # as PyBullet collides a moving mesh
            shape = item.geometry
            if hasattr(shape, "buildConvexHull") and shape.num_vertices > 3:
                try:
                    shape.buildConvexHull(False, "Qt")
                except RuntimeError:  # a vertex with too many neighbours (Centauro's pelvis)
                    shape.buildConvexHull(False, "QJ")  # joggled: qhull gives one coal takes
                item.geometry = shape.convex
        self.links = [
            self.kinematics.frames[g.parentFrame].name for g in self.geometry.geometryObjects
        ]
        adjacent = self._adjacent()
        for i, j in itertools.combinations(range(len(self.links)), 2):
            a, b = self.links[i], self.links[j]
            if a != b and frozenset((a, b)) not in adjacent:
                self.geometry.addCollisionPair(pin.CollisionPair(i, j))
        self.data = self.kinematics.createData()
        self._fresh_data()
        at_zero = self._meeting(self._q({}))  # within the clearance: they are built so
        for index in sorted(at_zero, reverse=True):
            self.geometry.removeCollisionPair(self.geometry.collisionPairs[index])
        self._fresh_data()

    def _fresh_data(self) -> None:
        self.geometry_data = self._new_data()
        self._apart: dict[frozenset[str], pin.GeometryData] = {}

    def _new_data(self) -> pin.GeometryData:
        data = pin.GeometryData(self.geometry)
        for request in data.collisionRequests:
            request.security_margin = CLEARANCE
        return data

    def _adjacent(self) -> set[frozenset[str]]:
        """Pairs of links joined by one joint, fixed joints merged."""
        group: dict[str, str] = {}
        for link in self.model.links:
            top = link
            joint = self.model.parent_joint(top)
            while joint is not None and joint.type == "fixed":
                top = joint.parent
                joint = self.model.parent_joint(top)
            group[link] = top
        members: dict[str, list[str]] = {}
        for link, top in group.items():
            members.setdefault(top, []).append(link)
        pairs = {
            frozenset(p) for links in members.values() for p in itertools.combinations(links, 2)
        }
        for joint in self.model.joints.values():
            if joint.type != "fixed":
                for a in members[group[joint.parent]]:
                    pairs.update(frozenset((a, b)) for b in members[group[joint.child]])
        return pairs

    def _q(self, values: Mapping[str, float]) -> np.ndarray:
        q = pin.neutral(self.kinematics)
        every = mimic_followers(self.model, {k: float(v) for k, v in values.items()})
        for name, spec in self.model.joints.items():
            if not spec.movable or not self.kinematics.existJointName(name):
                continue
            lower = -math.inf if spec.lower is None else spec.lower
            upper = math.inf if spec.upper is None else spec.upper
            value = every.get(name, min(max(0.0, lower), upper))
            joint = self.kinematics.joints[self.kinematics.getJointId(name)]
            if joint.nq == 2:  # a continuous joint: cos, sin
                q[joint.idx_q : joint.idx_q + 2] = (math.cos(value), math.sin(value))
            else:
                q[joint.idx_q] = value
        return q

    def _meeting(self, q: np.ndarray) -> list[int]:
        pin.computeCollisions(
            self.kinematics, self.data, self.geometry, self.geometry_data, q, False
        )
        return [i for i, r in enumerate(self.geometry_data.collisionResults) if r.isCollision()]

    def meeting(self, values: Mapping[str, float]) -> list[tuple[str, str]]:
        """The pairs of links that meet with ``values`` set (other joints at zero)."""
        pairs = self.geometry.collisionPairs
        found = []
        for index in self._meeting(self._q(values)):
            pair = pairs[index]
            found.append((self.links[pair.first], self.links[pair.second]))
        return sorted(set(found))

    def touches(self, values: Mapping[str, float], within: frozenset[str] = frozenset()) -> bool:
        """Whether any counted pair meets with ``values`` set, leaving out pairs of two links
        ``within`` one group (a hand's fingers meeting one another at their limits say
        nothing of where its arm parks)."""
        q = self._q(values)
        return pin.computeCollisions(
            self.kinematics, self.data, self.geometry, self._data_apart(within), q, True
        )

    def _data_apart(self, within: frozenset[str]) -> pin.GeometryData:
        """Collision data with the pairs inside ``within`` switched off, kept per group."""
        if not within:
            return self.geometry_data
        if within not in self._apart:
            data = self._new_data()
            for index, pair in enumerate(self.geometry.collisionPairs):
                if self.links[pair.first] in within and self.links[pair.second] in within:
                    data.deactivateCollisionPair(index)
            self._apart[within] = data
        return self._apart[within]

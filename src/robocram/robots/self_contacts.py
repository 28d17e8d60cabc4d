"""Which links of a robot meet in a configuration, on their collision shapes, without physics.

The draft has no world to ask (only ``robocram.world`` runs PyBullet), so it checks a
pose it proposes through pinocchio's geometry (coal underneath), meshes as their convex
hulls as PyBullet collides them (a concave torso's hull reaches far past its mesh), as
MoveIt's setup
assistant does before it writes an SRDF: pairs of links joined by one joint (fixed
joints merged), and pairs that already meet with every joint at zero (within limits),
are left out; every other pair counts. A pair meeting at zero that some seeded pose parts
(an arm hanging beside the pelvis) counts where a turned joint (a waist) moves a parked
arm's link against the other: Centauro's parked arm met its pelvis as the waist turned.
"""

from __future__ import annotations

import itertools
import math
import random
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

SAMPLES = 16  # seeded poses that tell a pair built meeting from one resting together at zero
SEED = 0
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
        self._resting: dict[int, frozenset[str]] = {}
        self._fresh_data()
        at_zero = set(self._meeting(self._q({})))  # within the clearance: they are built so,
        built = set(at_zero)  # unless a seeded pose parts them: then they rest so at zero
        rng = random.Random(SEED)
        for _ in range(SAMPLES):
            built &= set(self._meeting(self._q(self._sample(rng))))
        resting = {self._names(self.geometry.collisionPairs[i]) for i in at_zero - built}
        for index in sorted(at_zero, reverse=True):
            if index in built:
                self.geometry.removeCollisionPair(self.geometry.collisionPairs[index])
        self._resting = {
            index: self._between(*names)
            for index, pair in enumerate(self.geometry.collisionPairs)
            if (names := self._names(pair)) in resting
        }
        self._fresh_data()

    def _names(self, pair: pin.CollisionPair) -> tuple[str, str]:
        return self.links[pair.first], self.links[pair.second]

    def _between(self, a: str, b: str) -> frozenset[str]:
        """The joints between links ``a`` and ``b``: those that move one against the other."""

        def above(link: str) -> set[str]:
            found = set()
            joint = self.model.parent_joint(link)
            while joint is not None:
                found.add(joint.name)
                joint = self.model.parent_joint(joint.parent)
            return found

        return frozenset(above(a) ^ above(b))

    def _sample(self, rng: random.Random) -> dict[str, float]:
        """Every movable joint at a seeded value within its limits (+-pi where unlimited)."""
        values = {}
        for name, spec in self.model.joints.items():
            if spec.movable and spec.mimic is None:
                lower = -math.pi if spec.lower is None else spec.lower
                upper = math.pi if spec.upper is None else spec.upper
                values[name] = rng.uniform(lower, upper)
        return values

    def _fresh_data(self) -> None:
        self._kept: dict[frozenset[int], pin.GeometryData] = {}
        self.geometry_data = self._data(frozenset())

    def _data(self, counted: frozenset[int]) -> pin.GeometryData:
        """Collision data with the pairs that rest together at zero switched off, unless
        ``counted`` (kept per set)."""
        key = counted
        if key not in self._kept:
            data = pin.GeometryData(self.geometry)
            for request in data.collisionRequests:
                request.security_margin = CLEARANCE
            for index in self._resting:
                if index not in counted:
                    data.deactivateCollisionPair(index)
            self._kept[key] = data
        return self._kept[key]

    def _turned_against(self, turned: Mapping[str, float], parts: frozenset[str]) -> frozenset[int]:
        """The resting pairs with a link in ``parts`` that a joint of ``turned`` moves
        against the other link."""
        if not turned or not parts:
            return frozenset()
        names = set(turned) | set(mimic_followers(self.model, dict(turned)))
        pairs = self.geometry.collisionPairs
        return frozenset(
            i
            for i, joints in self._resting.items()
            if joints & names and not parts.isdisjoint(self._names(pairs[i]))
        )

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
        data = self.geometry_data
        pin.computeCollisions(self.kinematics, self.data, self.geometry, data, q, False)
        active = data.activeCollisionPairs
        return [i for i, r in enumerate(data.collisionResults) if active[i] and r.isCollision()]

    def meeting(self, values: Mapping[str, float]) -> list[tuple[str, str]]:
        """The pairs of links that meet with ``values`` set (other joints at zero)."""
        pairs = self.geometry.collisionPairs
        return sorted({self._names(pairs[i]) for i in self._meeting(self._q(values))})

    def touches(
        self,
        values: Mapping[str, float],
        turned: Mapping[str, float] | None = None,
        parts: frozenset[str] = frozenset(),
    ) -> bool:
        """Whether any counted pair meets with ``values`` (and ``turned``) set; a pair
        resting together at zero counts where a joint of ``turned`` moves its link of
        ``parts`` against the other."""
        q = self._q({**values, **(turned or {})})
        data = self._data(self._turned_against(turned or {}, parts))
        return pin.computeCollisions(self.kinematics, self.data, self.geometry, data, q, True)

"""Fast collision checks of one robot's configurations, on pinocchio and coal.

A planner checks thousands of configurations of one arm per motion; stepping PyBullet for
each costs ~0.5 ms. A :class:`CollisionScene` takes the world once (static geometry
where it stands now, what the robot holds, its other joints' values) and then checks a
configuration of the planned joints in C++: forward kinematics, a broadphase over the
geometry that can meet, and coal's narrow phase on the pairs that remain.

A scene holds its own pinocchio ``Data`` and ``GeometryData``: use it from one thread at
a time and give each thread its own :meth:`copy` (cheap: the models are shared). It
pickles as its world snapshot and is rebuilt in the receiving process.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.motion.hand_contact import HandContact
from robocram.motion.joint_slots import JointSlots
from robocram.motion.scene_geometry import SceneGeometry, build_geometry
from robocram.motion.scene_snapshot import SceneSnapshot
from robocram.robots.lazy_library import LazyLibrary
from robocram.world import RobotHandle

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")


class CollisionScene:
    """A snapshot of the world around one robot, for fast checks of configurations of some
    of its joints (:attr:`joints`, in that order); the base stays where it stands."""

    def __init__(
        self,
        snapshot: SceneSnapshot,
        geometry: SceneGeometry | None = None,
        allow_at: Sequence[Sequence[float] | NDArray[np.float64]] = (),
    ) -> None:
        self.snapshot = snapshot
        self.joints: tuple[str, ...] = snapshot.joints
        if geometry is None:
            geometry = build_geometry(snapshot)
            self._geometry = geometry
            self._slots = JointSlots(geometry.kinematics, snapshot.joints, geometry.q0)
            fulls = [geometry.q0, *(self._slots.full(q) for q in allow_at)]
            self._drop_pairs(self._own_contacts(fulls))
            self._new_data()
        else:
            self._geometry = geometry
            self._slots = JointSlots(geometry.kinematics, snapshot.joints, geometry.q0)
            self._new_data()

    @classmethod
    def of(
        cls,
        robot: RobotHandle,
        joints: Sequence[str],
        *,
        allowed_links: Collection[str] = (),
        margin: float = 0.0,
        allow_at: Sequence[Sequence[float] | NDArray[np.float64]] = (),
        hand: HandContact | None = None,
    ) -> CollisionScene:
        """Take the world around ``robot`` now, to check values of ``joints``.

        ``allowed_links`` may touch anything (CRAM's ``allow_hand``); ``margin`` [m]
        grows every shape, for a safety distance; the robot's own contacts at the
        configurations ``allow_at`` (a goal a finer check accepted) are left out; ``hand``'s
        links are not checked against what it may touch (the world bounds how deep).
        """
        snapshot = SceneSnapshot.take(robot, joints, allowed_links, margin, hand)
        return cls(snapshot, allow_at=allow_at)

    def _new_data(self) -> None:
        """This scene's own data: pinocchio's, coal's and two broadphase managers.

        The static side (world and robot parts no planned joint moves) is put in its tree
        once; a check updates only the moving side's tree and tests it against the static
        one and itself, so the kitchen's touching boxes are never tested among themselves.
        """
        geo = self._geometry
        model = geo.kinematics.model
        self._data = model.createData()
        self._geometry_data = geo.geometry.createData()
        _set_requests(self._geometry_data, self.snapshot.margin)
        moving, fixed = geo.sides()
        self._moving = pin.BroadPhaseManager_DynamicAABBTreeCollisionManager(
            model, moving, self._geometry_data
        )
        self._fixed = pin.BroadPhaseManager_DynamicAABBTreeCollisionManager(
            model, fixed, self._geometry_data
        )
        pin.updateGeometryPlacements(model, self._data, geo.geometry, self._geometry_data, geo.q0)
        self._fixed.update(False)
        self._first = pin.CollisionCallBackDefault(geo.geometry, self._geometry_data, True)
        self._collect = pin.CollisionCallBackCollect(
            geo.geometry, self._geometry_data, max(1, len(geo.pair_labels))
        )

    def allow_own_contacts_at(self, q: Sequence[float] | NDArray[np.float64]) -> None:
        """Leave out the robot's own pairs (and with what it holds) touching at ``q``.

        For a configuration a finer check already accepted (an IK goal checked on the
        world's meshes), so that the convex hulls of neighbouring links do not refuse it.
        Cheaper when given to the constructor (``allow_at``): the data is built once.
        """
        self._drop_own_contacts([self._slots.full(q)])

    def _drop_own_contacts(self, fulls: Sequence[NDArray[np.float64]]) -> None:
        """Remove the robot-robot and robot-held pairs touching at any of ``fulls`` (the
        snapshot's own configuration first), then build the data again for what is left:
        removed pairs cost the checks nothing, unlike switched-off ones."""
        geo = self._geometry
        kinds = [o.kind for o in geo.owners]
        drop = {
            k for full in fulls for k in self._pairs_at(full)
            if kinds[geo.geometry.collisionPairs[k].second] != "static"
        }  # fmt: skip
        if self._drop_pairs(drop):
            self._new_data()

    def _own_contacts(self, fulls: Sequence[NDArray[np.float64]]) -> set[int]:
        """Indices of the robot-robot and robot-held pairs touching at any of ``fulls``.

        Found on a copy of the geometry holding only those pairs: its data costs a few
        milliseconds, the full scene's (thousands of static pairs) tens, and a new scene
        builds that only once, after the drop.
        """
        geo = self._geometry
        kinds = [o.kind for o in geo.owners]
        pairs = geo.geometry.collisionPairs
        own = [k for k, pair in enumerate(pairs) if kinds[pair.second] != "static"]
        if not own:
            return set()
        geometry = geo.geometry.copy()
        geometry.removeAllCollisionPairs()
        for k in own:
            geometry.addCollisionPair(pin.CollisionPair(pairs[k].first, pairs[k].second))
        geometry_data = geometry.createData()
        _set_requests(geometry_data, self.snapshot.margin)
        model = geo.kinematics.model
        data = model.createData()
        found: set[int] = set()
        for full in fulls:
            pin.computeCollisions(model, data, geometry, geometry_data, full, False)
            results = geometry_data.collisionResults
            found.update(k for k, result in zip(own, results, strict=True) if result.isCollision())
        return found

    def _drop_pairs(self, drop: Collection[int]) -> bool:
        """Remove the pairs at indices ``drop`` from the geometry; whether any were."""
        if not drop:
            return False
        geo = self._geometry
        pairs = geo.geometry.collisionPairs
        dropped = [pin.CollisionPair(pairs[k].first, pairs[k].second) for k in sorted(drop)]
        for pair in dropped:  # one by one: a few, and the others keep their order
            geo.geometry.removeCollisionPair(pair)
        geo.pair_labels = [lab for k, lab in enumerate(geo.pair_labels) if k not in drop]
        geo.forget_sides()
        return True

    def _place(self, full: NDArray[np.float64]) -> None:
        geo = self._geometry
        pin.updateGeometryPlacements(
            geo.kinematics.model, self._data, geo.geometry, self._geometry_data, full
        )
        self._moving.update(False)

    @property
    def pair_count(self) -> int:
        """How many geometry pairs a full check may test (after culling and rules)."""
        return len(self._geometry.pair_labels)

    @property
    def geometry_count(self) -> int:
        """How many geometry objects the scene holds (robot, held and static)."""
        return int(self._geometry.geometry.ngeoms)

    def configuration(self, q: Sequence[float] | NDArray[np.float64]) -> NDArray[np.float64]:
        """The robot's full pinocchio configuration for ``q`` (values of :attr:`joints`)."""
        return self._slots.full(q)

    def is_free(self, q: Sequence[float] | NDArray[np.float64]) -> bool:
        """Whether nothing collides at ``q``; stops at the first collision."""
        self._place(self._slots.full(q))
        first = self._first
        self._moving.collide(self._fixed, first)  # each collide starts the callback anew
        if not first.collision:
            self._moving.collide(first)
        return not first.collision

    def colliding(
        self, q: Sequence[float] | NDArray[np.float64], first_only: bool = False
    ) -> list[tuple[str, str]]:
        """``(robot link or held object, other)`` pairs in contact at ``q``; empty: free.

        Other is an object name, ``object/link`` for objects of several links, or a robot
        link for a self-collision. ``first_only`` stops at the first.
        """
        labels = self._geometry.pair_labels
        found: dict[tuple[str, str], None] = {}
        for k in self._pairs_at(self._slots.full(q), first_only):
            found[labels[k]] = None
        return list(found)

    def _pairs_at(self, full: NDArray[np.float64], first_only: bool = False) -> list[int]:
        """Indices of the collision pairs in contact at ``full`` (sorted)."""
        self._place(full)
        collect = self._collect
        self._moving.collide(self._fixed, collect)  # each collide starts the callback anew
        candidates = {int(k) for k in collect.pair_indexes}
        self._moving.collide(collect)
        candidates.update(int(k) for k in collect.pair_indexes)
        geo = self._geometry
        hits = []
        for k in sorted(candidates):
            if pin.computeCollision(geo.geometry, self._geometry_data, k):
                hits.append(k)
                if first_only:
                    break
        return hits

    def copy(self) -> CollisionScene:
        """A scene sharing this one's models with its own data, for another thread."""
        return CollisionScene(self.snapshot, self._geometry)

    def __reduce__(self) -> tuple[type[CollisionScene], tuple[SceneSnapshot]]:
        return (CollisionScene, (self.snapshot,))


def _set_requests(geometry_data: pin.GeometryData, margin: float) -> None:
    """Every pair's request with ``margin`` [m] and no contact (a yes/no answer: GJK only,
    no EPA). pinocchio makes all of a data's requests alike: when the first already is
    so (no margin), so are the others, and the walk over thousands of them is spared."""
    requests = geometry_data.collisionRequests
    if not len(requests):
        return
    first = requests[0]
    if first.security_margin == margin and not first.enable_contact:
        return
    for request in requests:
        request.security_margin = margin
        request.enable_contact = False

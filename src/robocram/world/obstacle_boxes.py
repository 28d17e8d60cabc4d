"""The bounds of every link a moving body could hit, read once while only that body moves.

A motion check asks "what is near the arm?" tens of times for one segment, and between
those questions only the robot (and what it carries) moves. Asking Bullet's broadphase
afresh each time costs two calls per robot link plus Python per overlapping link; with the
others' bounds read once into arrays, one vectorised comparison per question finds the
same overlapping pairs.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from functools import cached_property, partial
from itertools import chain
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from robocram.world.derived import Derived
from robocram.world.pybullet_backend import pybullet
from robocram.world.versions import Stamp, Versions
from robocram.world.world_object import WorldObject


class _Client(Protocol):
    def client(self) -> int: ...


class BoxWorld(Protocol):
    """What reading obstacle bounds asks of a world (not the whole facade, which names
    this module's table: the layering test forbids the cycle)."""

    @property
    def physics(self) -> _Client: ...
    @property
    def versions(self) -> Versions: ...

    def objects(self, type: str | None = None) -> list[WorldObject]: ...  # noqa: A002


FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class ObstacleBoxes:
    """Per link of every body but ``skipped``: its body, index, name and bounds [m].

    Valid only while those bodies stay where they were when it was read; the caller (a
    check that moves one robot's joints, :class:`robocram.motion.BulletScene`) keeps it for
    as long as that holds.
    """

    skipped: frozenset[str]
    objects: tuple[WorldObject, ...]
    indices: tuple[int, ...]
    names: tuple[str, ...]
    low: FloatArray  # (links, 3)
    high: FloatArray  # (links, 3)

    @classmethod
    def of(cls, world: BoxWorld, skip: Iterable[str]) -> ObstacleBoxes:
        """Read the bounds of every link of every object not named in ``skip``."""
        skipped = frozenset(skip)
        rows = [_BodyBoxes.read(world, o) for o in world.objects() if o.name not in skipped]
        return cls.joined(skipped, rows)

    @classmethod
    def joined(cls, skipped: frozenset[str], rows: list[_BodyBoxes]) -> ObstacleBoxes:
        """The table of the bodies' ``rows``, in their order."""
        low = np.concatenate([r.low for r in rows]) if rows else np.zeros((0, 3))
        high = np.concatenate([r.high for r in rows]) if rows else np.zeros((0, 3))
        low.flags.writeable = high.flags.writeable = False  # a kept table is shared
        flat = chain.from_iterable  # the same tuples as nested loops, built in C
        return cls(
            skipped,
            tuple(flat((r.obj,) * len(r.indices) for r in rows)),
            tuple(flat(r.indices for r in rows)),
            tuple(flat(r.names for r in rows)),
            low,
            high,
        )

    @cached_property
    def low_high(self) -> FloatArray:
        """(links, 6): each row's low corner and its negated high one, so that one
        comparison with a query box's high corner and negated low one tells an overlap
        (negating is exact: the same answer as comparing the corners)."""
        table = np.concatenate((self.low, -self.high), axis=1)
        table.flags.writeable = False
        return table

    def covers(self, obj: WorldObject, skip: set[str]) -> bool:
        """Whether every body a query about ``obj`` (skipping ``skip``) must look at is here."""
        return self.skipped <= skip | {obj.name}

    def overlapping(
        self, low: FloatArray, high: FloatArray, skip: set[str]
    ) -> Iterator[tuple[int, int]]:
        """``(query box, table row)`` per pair of overlapping boxes: ``low``/``high`` are
        (boxes, 3); rows of objects named in ``skip`` are left out."""
        if not len(self.names) or not len(low):
            return
        query = np.concatenate((high, -low), axis=1)  # (boxes, 6): a row's low_high <= it
        table = self.low_high
        near = np.flatnonzero(
            (table <= query.max(axis=0)).all(axis=1)
        )  # rows within the bounds of all query boxes: few, so the pairwise test is small
        if not near.size:
            return
        hits = (table[near][None, :, :] <= query[:, None, :]).all(axis=2)
        for box, column in zip(*np.nonzero(hits), strict=True):
            row = int(near[column])
            if self.objects[row].name not in skip:
                yield int(box), row


@dataclass(frozen=True)
class _BodyBoxes:
    """The bounds of one body's links with shapes, and its movable joints' values then."""

    obj: WorldObject
    indices: tuple[int, ...]
    names: tuple[str, ...]
    low: FloatArray  # (links, 3)
    high: FloatArray  # (links, 3)
    joints: tuple[float, ...] = ()  # [rad | m] per movable joint (empty: not read)

    @classmethod
    def read(cls, world: BoxWorld, obj: WorldObject) -> _BodyBoxes:
        """Read ``obj``'s bounds as it stands now."""
        cid = world.physics.client()
        links = [(i, n) for i, n in obj.index_names().items() if i in obj.colliders]
        table = np.array(
            [pybullet.getAABB(*obj.locate(i), physicsClientId=cid) for i, _ in links],
            dtype=float,
        ).reshape(-1, 6)
        return cls(
            obj, tuple(i for i, _ in links), tuple(n for _, n in links),
            table[:, :3], table[:, 3:], _joint_values(obj, cid),
        )  # fmt: skip

    def moved(self, world: BoxWorld, below: tuple[frozenset[int], ...]) -> _BodyBoxes:
        """These bounds after the body's joints moved (its pose did not): only the rows
        ``below`` a joint whose value changed (per movable joint: the rows of the links it
        moves) are read again. The others' links stand where they stood: the same bounds."""
        cid = world.physics.client()
        joints = _joint_values(self.obj, cid)
        changed = [k for k, (a, b) in enumerate(zip(joints, self.joints, strict=True)) if a != b]
        rows = sorted(set().union(*(below[k] for k in changed)))
        low, high = self.low, self.high
        if rows:
            low, high = low.copy(), high.copy()
            for row in rows:
                low[row], high[row] = pybullet.getAABB(
                    self.obj.body_id, self.indices[row], physicsClientId=cid
                )
        return _BodyBoxes(self.obj, self.indices, self.names, low, high, joints)


def _joint_values(obj: WorldObject, cid: int) -> tuple[float, ...]:
    """The values of a one-body object's movable joints, in their order (empty for an
    object of several bodies: its bounds are read whole)."""
    if obj.parts or not obj.movable_joints:
        return ()
    slots = [obj.joint_index[name] for name in obj.movable_joints]
    states = pybullet.getJointStates(obj.body_id, slots, physicsClientId=cid) or ()
    return tuple(float(state[0]) for state in states)


def _rows_below(obj: WorldObject, boxes: _BodyBoxes, cid: int) -> tuple[frozenset[int], ...]:
    """Per movable joint of a one-body object: the rows of ``boxes`` whose links it moves
    (its child link and everything below it)."""
    parent = {
        i: pybullet.getJointInfo(obj.body_id, i, physicsClientId=cid)[16]
        for i in range(pybullet.getNumJoints(obj.body_id, physicsClientId=cid))
    }

    def moves(joint: int, link: int) -> bool:
        while link >= 0:
            if link == joint:
                return True
            link = parent[link]
        return False

    return tuple(
        frozenset(row for row, link in enumerate(boxes.indices) if moves(obj.joint_index[j], link))
        for j in obj.movable_joints
    )


def _table_stamp(versions: Versions, key: tuple[frozenset[str], tuple[str, ...]]) -> Stamp:
    """A table of the bodies named in ``key[1]`` depends on each one's pose and joints."""
    return versions.bodies(key[1])


@dataclass
class KeptObstacleBoxes:
    """Obstacle bounds kept with a world: a body's are read again only when its pose or
    joints changed (:meth:`Versions.body`), instead of one backend call per link. Arm
    motion checks and base drives ask for them many times per plan while only the robot
    and what it holds move."""

    _bodies: dict[str, tuple[Stamp, _BodyBoxes]] = field(default_factory=dict)  # per body:
    # its bounds and the counters they were read at (:meth:`Versions.body`)
    _below: Derived[str, tuple[frozenset[int], ...]] = field(
        default_factory=lambda: Derived(Versions.created)
    )  # per one-body object: per movable joint, the rows of the links it moves
    _tables: Derived[tuple[frozenset[str], tuple[str, ...]], ObstacleBoxes] = field(
        default_factory=lambda: Derived(_table_stamp, size=4)
    )  # the tables last asked for (a motion's checks and IK's skip different bodies)

    def boxes(self, world: BoxWorld, skip: Iterable[str]) -> ObstacleBoxes:
        """:meth:`ObstacleBoxes.of`, from the bodies' bounds kept while they stay put."""
        skipped = frozenset(skip)
        versions = world.versions
        objects = [obj for obj in world.objects() if obj.name not in skipped]

        def joined() -> ObstacleBoxes:
            return ObstacleBoxes.joined(skipped, [self._body(world, o) for o in objects])

        key = (skipped, tuple(o.name for o in objects))
        return self._tables.get(key, joined, versions)

    def _body(self, world: BoxWorld, obj: WorldObject) -> _BodyBoxes:
        """``obj``'s bounds: kept while it stays put; after only its joints moved (a
        drawer opened a step), read again below the joints that changed; else read whole."""
        stamp = world.versions.body(obj.name)
        kept = self._bodies.get(obj.name)
        if kept is not None and kept[0] == stamp:
            return kept[1]
        if kept is not None and kept[0][:2] == stamp[:2] and kept[1].joints:
            cid = world.physics.client()
            read = partial(_rows_below, obj, kept[1], cid)
            boxes = kept[1].moved(world, self._below.get(obj.name, read, world.versions))
        else:
            boxes = _BodyBoxes.read(world, obj)
        self._bodies[obj.name] = (stamp, boxes)
        return boxes

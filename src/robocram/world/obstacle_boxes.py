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
        return cls(
            skipped,
            tuple(o for r in rows for o in (r.obj,) * len(r.indices)),
            tuple(i for r in rows for i in r.indices),
            tuple(n for r in rows for n in r.names),
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
    """The bounds of one body's links with shapes."""

    obj: WorldObject
    indices: tuple[int, ...]
    names: tuple[str, ...]
    low: FloatArray  # (links, 3)
    high: FloatArray  # (links, 3)

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
            table[:, :3], table[:, 3:],
        )  # fmt: skip


def _table_stamp(versions: Versions, key: tuple[frozenset[str], tuple[str, ...]]) -> Stamp:
    """A table of the bodies named in ``key[1]`` depends on each one's pose and joints."""
    return versions.bodies(key[1])


@dataclass
class KeptObstacleBoxes:
    """Obstacle bounds kept with a world: a body's are read again only when its pose or
    joints changed (:meth:`Versions.body`), instead of one backend call per link. Arm
    motion checks and base drives ask for them many times per plan while only the robot
    and what it holds move."""

    _bodies: Derived[str, _BodyBoxes] = field(default_factory=lambda: Derived(Versions.body))
    _tables: Derived[tuple[frozenset[str], tuple[str, ...]], ObstacleBoxes] = field(
        default_factory=lambda: Derived(_table_stamp, size=4)
    )  # the tables last asked for (a motion's checks and IK's skip different bodies)

    def boxes(self, world: BoxWorld, skip: Iterable[str]) -> ObstacleBoxes:
        """:meth:`ObstacleBoxes.of`, from the bodies' bounds kept while they stay put."""
        skipped = frozenset(skip)
        versions = world.versions
        objects = [obj for obj in world.objects() if obj.name not in skipped]

        def joined() -> ObstacleBoxes:
            kept = self._bodies
            rows = [kept.get(o.name, partial(_BodyBoxes.read, world, o), versions) for o in objects]
            return ObstacleBoxes.joined(skipped, rows)

        key = (skipped, tuple(o.name for o in objects))
        return self._tables.get(key, joined, versions)

"""The bounds of every link a moving body could hit, read once while only that body moves.

A motion check asks "what is near the arm?" tens of times for one segment, and between
those questions only the robot (and what it carries) moves. Asking Bullet's broadphase
afresh each time costs two calls per robot link plus Python per overlapping link; with the
others' bounds read once into arrays, one vectorised comparison per question finds the
same overlapping pairs.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from robocram.world.contacts import _link_names
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_core import WorldCore
from robocram.world.world_object import WorldObject

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
    def of(cls, world: WorldCore, skip: Iterable[str]) -> ObstacleBoxes:
        """Read the bounds of every link of every object not named in ``skip``."""
        skipped = frozenset(skip)
        cid = world.physics_client()
        objects: list[WorldObject] = []
        indices: list[int] = []
        names: list[str] = []
        boxes: list[tuple[float, ...]] = []
        for obj in world.objects():
            if obj.name in skipped:
                continue
            for index, name in _link_names(obj).items():
                if index not in obj.colliders:
                    continue  # a frame without shapes hits nothing
                low, high = pybullet.getAABB(obj.body_id, index, physicsClientId=cid)
                objects.append(obj)
                indices.append(index)
                names.append(name)
                boxes.append((*low, *high))
        table = np.array(boxes, dtype=float).reshape(-1, 6)
        return cls(
            skipped, tuple(objects), tuple(indices), tuple(names), table[:, :3], table[:, 3:]
        )

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
        near = np.flatnonzero(
            (self.low <= high.max(axis=0)).all(axis=1) & (low.min(axis=0) <= self.high).all(axis=1)
        )  # rows within the bounds of all query boxes: few, so the pairwise test is small
        if not near.size:
            return
        hits = (
            (low[:, None, :] <= self.high[None, near, :])
            & (self.low[None, near, :] <= high[:, None, :])
        ).all(axis=2)
        for box, column in zip(*np.nonzero(hits), strict=True):
            row = int(near[column])
            if self.objects[row].name not in skip:
                yield int(box), row

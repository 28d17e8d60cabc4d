"""PyBullet's own answers about two links, with nothing of ours in between.

An audit that must not trust the planner's checker asks the physics engine directly: the
bounds PyBullet keeps for each link with collision shapes (``getAABB``) and the closest
points of one pair of links (``getClosestPoints``). Nothing is cached, bounded below or
skipped here: attachments, allowed contacts and adjacency are the caller's to decide.

A caller asking about the same links many times (the audit, per configuration) looks
their PyBullet addresses up once (:meth:`RawDistances.slots`) and asks by address
(:meth:`RawDistances.slot_bounds`, :meth:`RawDistances.slot_closest`,
:meth:`RawDistances.slot_distance`): the same calls with the same arguments, without the
name look-ups in between. An address holds while its body is not rebuilt.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.tf import Vector3
from robocram.world.errors import UnknownLinkError
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_object import WorldObject
from robocram.world.world_tables import ObjectRef

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade


@dataclass(frozen=True)
class LinkGap:
    """The signed distance [m] between two links (negative: penetration) and where."""

    distance: float  # [m] < 0: penetration depth
    position_on_a: Vector3  # [m] in map
    position_on_b: Vector3  # [m] in map


LinkSlot = tuple[int, int]  # PyBullet's (body id, link index) of one link


class RawDistances:
    """Link bounds and closest points of the bodies of one world, straight from PyBullet."""

    def __init__(self, world: WorldFacade) -> None:
        self.world = world

    def collision_links(self, obj: ObjectRef) -> list[str]:
        """The links of ``obj`` that have collision shapes (a single-shape body: its name)."""
        handle = self.world.object(obj)
        return [name for _, name in sorted(handle.collider_names().items())]

    def link_bounds(self, obj: ObjectRef, links: list[str]) -> list[tuple[Vector3, Vector3]]:
        """PyBullet's world-aligned bounds ``(low, high)`` [m] of each of ``links`` now."""
        handle = self.world.object(obj)
        cid = self.world.physics.client()
        found = []
        for link in links:
            low, high = pybullet.getAABB(*handle.locate(_index(handle, link)), physicsClientId=cid)
            found.append((tuple(low), tuple(high)))
        return found

    def slots(self, obj: ObjectRef, links: Sequence[str]) -> list[LinkSlot]:
        """PyBullet's ``(body, link index)`` of each of ``links`` of ``obj``."""
        handle = self.world.object(obj)
        return [handle.locate(_index(handle, link)) for link in links]

    def slot_bounds(self, slots: Sequence[LinkSlot]) -> NDArray[np.float64]:
        """(links, 2, 3): :meth:`link_bounds` of the links at ``slots``, low then high."""
        cid = self.world.physics.client()
        aabb = pybullet.getAABB
        flat: list[float] = []
        for body, index in slots:
            low, high = aabb(body, index, physicsClientId=cid)
            flat += low
            flat += high
        return np.array(flat, dtype=float).reshape(len(slots), 2, 3)

    def slot_closest(self, a: LinkSlot, b: LinkSlot, reach: float = 0.0) -> LinkGap | None:
        """:meth:`closest` of the links at slots ``a`` and ``b``."""
        points = pybullet.getClosestPoints(
            a[0], b[0], reach, linkIndexA=a[1], linkIndexB=b[1],
            physicsClientId=self.world.physics.client(),
        )  # fmt: skip
        if not points:
            return None
        nearest = min(points, key=lambda p: p[8])
        return LinkGap(float(nearest[8]), tuple(nearest[5]), tuple(nearest[6]))

    def slot_distance(self, a: LinkSlot, b: LinkSlot, reach: float = 0.0) -> float | None:
        """:meth:`slot_closest`'s distance alone (the same call, without building where)."""
        points = pybullet.getClosestPoints(
            a[0], b[0], reach, linkIndexA=a[1], linkIndexB=b[1],
            physicsClientId=self.world.physics.client(),
        )  # fmt: skip
        if not points:
            return None
        return float(min(p[8] for p in points))

    def links_moved_by(self, obj: ObjectRef, joint: str) -> list[str]:
        """The links of ``obj`` with collision shapes that setting ``joint`` moves: its
        child link and those below it, by PyBullet's parent indices. Every one for an
        object of several bodies or with mimic joints (a joint may move others)."""
        handle = self.world.object(obj)
        links = self.collision_links(handle)
        model = handle.urdf_model
        moved = handle.joint_index.get(joint)
        if (
            moved is None
            or handle.parts
            or (model is not None and any(j.mimic for j in model.joints.values()))
        ):
            return links
        cid = self.world.physics.client()
        count = pybullet.getNumJoints(handle.body_id, physicsClientId=cid)
        parent = [pybullet.getJointInfo(handle.body_id, i, physicsClientId=cid)[16]
                  for i in range(count)]  # fmt: skip

        def below(index: int) -> bool:
            while index >= 0:
                if index == moved:
                    return True
                index = parent[index]
            return False

        return [link for link in links if below(_index(handle, link))]

    def closest(
        self, a: ObjectRef, link_a: str, b: ObjectRef, link_b: str, reach: float = 0.0
    ) -> LinkGap | None:
        """The nearest points of ``link_a`` of ``a`` and ``link_b`` of ``b`` within ``reach``
        [m] (``None``: farther apart); the least of PyBullet's closest points."""
        first, second = self.world.object(a), self.world.object(b)
        (body_a, index_a), (body_b, index_b) = (
            first.locate(_index(first, link_a)), second.locate(_index(second, link_b))
        )  # fmt: skip
        points = pybullet.getClosestPoints(
            body_a,
            body_b,
            reach,
            linkIndexA=index_a,
            linkIndexB=index_b,
            physicsClientId=self.world.physics.client(),
        )
        if not points:
            return None
        nearest = min(points, key=lambda p: p[8])
        return LinkGap(float(nearest[8]), tuple(nearest[5]), tuple(nearest[6]))


def _index(handle: WorldObject, link: str) -> int:
    """PyBullet's index of ``link``; a single-shape body's one link is its name (the base)."""
    index = handle.link_index.get(link)
    if index is not None:
        return index
    if link == handle.name:
        return -1
    raise UnknownLinkError(handle.name, link, handle.link_index)

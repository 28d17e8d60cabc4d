"""PyBullet's own answers about two links, with nothing of ours in between.

An audit that must not trust the planner's checker asks the physics engine directly: the
bounds PyBullet keeps for each link with collision shapes (``getAABB``) and the closest
points of one pair of links (``getClosestPoints``). Nothing is cached, bounded below or
skipped here: attachments, allowed contacts and adjacency are the caller's to decide.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

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

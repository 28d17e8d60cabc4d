"""World-aligned bounds of single links, for footprints and occupancy grids."""

from __future__ import annotations

import pybullet

from robocram.tf import Vector3
from robocram.world.world_core import ObjectRef, WorldCore


def link_aabb(world: WorldCore, obj: ObjectRef, link: str) -> tuple[Vector3, Vector3]:
    """World-aligned bounds ``(lower, upper)`` [m] of one link of ``obj``.

    Raises:
        UnknownLinkError: ``obj`` has no link ``link``.
    """
    handle = world.object(obj)
    index = world._link_index(handle, link)
    low, high = pybullet.getAABB(handle.body_id, index, physicsClientId=world._cid())
    return (low[0], low[1], low[2]), (high[0], high[1], high[2])


def link_aabbs(world: WorldCore, obj: ObjectRef) -> dict[str, tuple[Vector3, Vector3]]:
    """:func:`link_aabb` of every link of ``obj`` by link name (the root link included)."""
    return {link: link_aabb(world, obj, link) for link in world.link_names(obj)}

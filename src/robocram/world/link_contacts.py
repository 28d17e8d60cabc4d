"""Which links of a body touch other bodies, found through Bullet's broadphase.

Asking Bullet for the closest points of a robot and a whole kitchen (hundreds of links)
costs ~2 ms; a location validator asks that for every candidate stand. Here each link's
bounds (grown by the contact distance) ask the broadphase which links of other bodies
overlap them, and only those pairs get closest points. What counts as touching is what
:mod:`~robocram.world.contacts` says: the body's carried objects and itself never do.
"""

from __future__ import annotations

from collections.abc import Iterable

import pybullet

from robocram.world.contacts import CONTACT_DISTANCE, _carried_with, _link_names
from robocram.world.world_core import WorldCore
from robocram.world.world_object import WorldObject


def link_contacts(
    world: WorldCore,
    obj: WorldObject,
    links: Iterable[str] | None = None,
    ignore: Iterable[WorldObject] = (),
    distance: float = CONTACT_DISTANCE,
) -> list[tuple[str, str]]:
    """``(link of obj, other object)`` pairs nearer than ``distance`` [m], each once.

    ``links`` limits the links of ``obj`` asked about (default: all of them).
    """
    cid = world.physics_client()
    skip_names = _carried_with(world, obj) | {o.name for o in ignore}
    by_body = {o.body_id: o for o in world.objects() if o.name not in skip_names}
    names = _link_names(obj)
    indices = names if links is None else {obj.link_index[name]: name for name in links}
    found: dict[tuple[str, str], None] = {}
    for index, link in indices.items():
        low, high = pybullet.getAABB(obj.body_id, index, physicsClientId=cid)
        low = [v - distance for v in low]
        high = [v + distance for v in high]
        overlapping = pybullet.getOverlappingObjects(low, high, physicsClientId=cid) or ()
        for body, other_link in overlapping:
            other = by_body.get(body)
            if other is None or (link, other.name) in found:
                continue
            if pybullet.getClosestPoints(
                obj.body_id, body, distance, linkIndexA=index, linkIndexB=other_link,
                physicsClientId=cid,
            ):  # fmt: skip
                found[(names.get(index, link), other.name)] = None
    return list(found)

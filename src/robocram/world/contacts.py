"""Contacts and collisions between bodies, ignoring what a robot carries.

Objects attached to a robot touch it by design, so a robot and its attached objects never
count as colliding with each other; a robot's self-collisions are not checked either.
"""

from __future__ import annotations

from collections.abc import Iterable

import pybullet

from robocram.world.world_core import WorldCore
from robocram.world.world_object import WorldObject

CONTACT_DISTANCE = 0.002  # [m] closer than this counts as touching


def _carried_with(world: WorldCore, obj: WorldObject) -> set[str]:
    """Names of bodies rigidly linked to ``obj`` through attachments, ``obj`` included."""
    group = {obj.name}
    changed = True
    while changed:
        changed = False
        for att in world._attachments.values():
            if (att.obj in group) != (att.robot in group):
                group |= {att.obj, att.robot}
                changed = True
    return group


def touching(world: WorldCore, a: WorldObject, b: WorldObject, distance: float) -> bool:
    """Whether the closest points of ``a`` and ``b`` are nearer than ``distance`` [m]."""
    points = pybullet.getClosestPoints(a.body_id, b.body_id, distance, physicsClientId=world.client)
    return bool(points)


def collisions(
    world: WorldCore,
    obj: WorldObject,
    ignore: Iterable[WorldObject] = (),
    distance: float = CONTACT_DISTANCE,
) -> list[WorldObject]:
    """Objects in contact with or penetrating ``obj``, except attached ones and ``ignore``."""
    skip = _carried_with(world, obj) | {o.name for o in ignore}
    return [o for o in world.objects() if o.name not in skip and touching(world, obj, o, distance)]


def contact(world: WorldCore, a: WorldObject, b: WorldObject) -> bool:
    """Whether ``a`` and ``b`` touch; never for a robot and what it carries."""
    if a is b or b.name in _carried_with(world, a):
        return False
    return touching(world, a, b, CONTACT_DISTANCE)

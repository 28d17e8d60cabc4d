"""Contacts and collisions between bodies, ignoring what a robot carries.

Objects attached to a robot touch it by design, so a robot and its attached objects never
count as colliding with each other; a robot's self-collisions are not checked either.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import TYPE_CHECKING

from robocram.world.contact_point import ContactPoint
from robocram.world.errors import UnknownLinkError
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_object import WorldObject

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade

CONTACT_DISTANCE = 0.002  # [m] closer than this counts as touching


def _carried_with(world: WorldFacade, obj: WorldObject) -> set[str]:
    """Names of bodies rigidly linked to ``obj`` through attachments, ``obj`` included."""
    group = {obj.name}
    changed = True
    while changed:
        changed = False
        for att in world.bodies.all_attachments():
            if (att.obj in group) != (att.robot in group):
                group |= {att.obj, att.robot}
                changed = True
    return group


def _link_names(obj: WorldObject) -> dict[int, str]:
    """pybullet link index -> link name (the first name of each index)."""
    return obj.index_names()  # single-shape bodies: the base is the object itself


def _index(obj: WorldObject, link: str) -> int:
    index = obj.link_index.get(link)
    if index is None:
        raise UnknownLinkError(obj.name, link, obj.link_index)
    return index


def closest_points(
    world: WorldFacade,
    a: WorldObject,
    b: WorldObject,
    distance: float,
    link_a: str | None = None,
    link_b: str | None = None,
) -> list[ContactPoint]:
    """Closest points of ``a`` and ``b`` (or of the given links) nearer than ``distance``."""
    return _asked(world, a, b, distance, _body_pairs(a, b, link_a, link_b))


def links_closest_points(
    world: WorldFacade, a: WorldObject, links: Collection[str], b: WorldObject, distance: float
) -> list[ContactPoint]:
    """:func:`closest_points` of ``a`` and ``b`` whose point on ``a`` is on one of its
    ``links`` (by the first name of each link): asked of those links alone, so a hand's
    few links against a handle cost a fraction of the whole robot's (Bullet tests each
    pair of links it is asked about on its own, so the points are the same)."""
    slots = sorted(i for i, name in _link_names(a).items() if name in links and i in a.colliders)
    pairs = [
        (body_a, body_b, {"linkIndexA": index_a})
        for body_a, index_a in (a.locate(slot) for slot in slots)
        for body_b in b.bodies
    ]
    return _asked(world, a, b, distance, pairs)


def _asked(
    world: WorldFacade,
    a: WorldObject,
    b: WorldObject,
    distance: float,
    pairs: list[tuple[int, int, dict[str, int]]],
) -> list[ContactPoint]:
    """The closest points of each pair of bodies of ``pairs`` (with its link filters)."""
    cid = world.physics.client()
    points = [
        point
        for body_a, body_b, filters in pairs
        for point in pybullet.getClosestPoints(
            body_a, body_b, distance, physicsClientId=cid, **filters
        )
        or ()
    ]
    names_a, names_b = _link_names(a), _link_names(b)
    return [
        ContactPoint(
            a.name,
            b.name,
            names_a[a.slot(p[1], p[3])],
            names_b[b.slot(p[2], p[4])],
            tuple(p[5]),
            tuple(p[6]),
            tuple(p[7]),
            float(p[8]),
        )  # fmt: skip
        for p in points
    ]


def _body_pairs(
    a: WorldObject, b: WorldObject, link_a: str | None, link_b: str | None
) -> list[tuple[int, int, dict[str, int]]]:
    """The pybullet bodies to ask for closest points of ``a`` and ``b`` (or their links),
    each pair with its link filters: an object cut in parts is several bodies."""
    sides: list[list[tuple[int, dict[str, int]]]] = []
    for obj, link, key in ((a, link_a, "linkIndexA"), (b, link_b, "linkIndexB")):
        if link is None:
            sides.append([(body, {}) for body in obj.bodies])
        else:
            body, index = obj.locate(_index(obj, link))
            sides.append([(body, {key: index})])
    return [(ba, bb, fa | fb) for ba, fa in sides[0] for bb, fb in sides[1]]


def contact(world: WorldFacade, a: WorldObject, b: WorldObject) -> bool:
    """Whether ``a`` and ``b`` touch; never for a robot and what it carries."""
    if a is b or b.name in _carried_with(world, a):
        return False
    return bool(closest_points(world, a, b, CONTACT_DISTANCE))

"""Which links of a body touch other bodies, found through Bullet's broadphase.

Asking Bullet for the closest points of a robot and a whole kitchen (hundreds of links)
costs ~2 ms; a location validator asks that for every candidate stand, and an IK collision
check for every converged configuration. Here each link's bounds (grown by the contact
distance) ask the broadphase which links of other bodies overlap them, and only those
pairs get closest points. What counts as touching is what :mod:`~robocram.world.contacts`
says: the body's carried objects and itself never do.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from robocram.world.contacts import CONTACT_DISTANCE, _carried_with, _link_names
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_core import WorldCore
from robocram.world.world_object import WorldObject


def _overlaps(
    world: WorldCore,
    obj: WorldObject,
    links: Iterable[str] | None,
    skip: set[str],
    distance: float,
) -> Iterator[tuple[str, WorldObject, int, int]]:
    """``(link of obj, other object, other's link index, obj's link index)`` per pair of
    links whose bounds, grown by ``distance``, overlap; objects named in ``skip`` left out."""
    cid = world.physics_client()
    by_body = {o.body_id: o for o in world.objects() if o.name not in skip}
    names = _link_names(obj)
    indices = names if links is None else {obj.link_index[name]: name for name in links}
    for index, link in indices.items():
        low, high = pybullet.getAABB(obj.body_id, index, physicsClientId=cid)
        low = [v - distance for v in low]
        high = [v + distance for v in high]
        for body, other_link in (
            pybullet.getOverlappingObjects(low, high, physicsClientId=cid) or ()
        ):
            other = by_body.get(body)
            if other is not None:
                yield names.get(index, link), other, other_link, index


def _near(world: WorldCore, a: WorldObject, b: WorldObject, la: int, lb: int, d: float) -> bool:
    return bool(
        pybullet.getClosestPoints(
            a.body_id, b.body_id, d, linkIndexA=la, linkIndexB=lb,
            physicsClientId=world.physics_client(),
        )
    )  # fmt: skip


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
    skip = _carried_with(world, obj) | {o.name for o in ignore}
    found: dict[tuple[str, str], None] = {}
    for link, other, other_link, index in _overlaps(world, obj, links, skip, distance):
        if (link, other.name) not in found and _near(
            world, obj, other, index, other_link, distance
        ):
            found[(link, other.name)] = None
    return list(found)


def link_pairs_in_contact(
    world: WorldCore,
    obj: WorldObject,
    ignore: Iterable[WorldObject] = (),
    distance: float = CONTACT_DISTANCE,
    links: Iterable[str] | None = None,
) -> list[tuple[str, WorldObject, str]]:
    """``(link of obj, other object, its link)`` triples nearer than ``distance`` [m], each once.

    Unlike :func:`link_contacts` nothing is skipped for being carried: the caller says in
    ``ignore`` what may touch (a robot and what it holds, the floor).
    """
    skip = {obj.name} | {o.name for o in ignore}
    found: dict[tuple[str, str, str], tuple[str, WorldObject, str]] = {}
    for link, other, other_link, index in _overlaps(world, obj, links, skip, distance):
        other_name = _link_names(other).get(other_link, other.name)
        key = (link, other.name, other_name)
        if key not in found and _near(world, obj, other, index, other_link, distance):
            found[key] = (link, other, other_name)
    return list(found.values())


def link_distances(
    world: WorldCore,
    obj: WorldObject,
    ignore: Iterable[WorldObject] = (),
    distance: float = CONTACT_DISTANCE,
    links: Iterable[str] | None = None,
) -> list[tuple[str, WorldObject, str, float]]:
    """``(link of obj, other object, its link, distance [m])`` for each pair of links
    nearer than ``distance``, with the smallest distance between them (negative when they
    penetrate). ``links`` limits the links of ``obj`` asked about (default: all)."""
    skip = {obj.name} | {o.name for o in ignore}
    cid = world.physics_client()
    found: dict[tuple[str, str, str], tuple[str, WorldObject, str, float]] = {}
    for link, other, other_link, index in _overlaps(world, obj, links, skip, distance):
        points = pybullet.getClosestPoints(
            obj.body_id, other.body_id, distance, linkIndexA=index, linkIndexB=other_link,
            physicsClientId=cid,
        )  # fmt: skip
        if not points:
            continue
        nearest = min(float(p[8]) for p in points)
        other_name = _link_names(other).get(other_link, other.name)
        key = (link, other.name, other_name)
        if key not in found or nearest < found[key][3]:
            found[key] = (link, other, other_name, nearest)
    return list(found.values())


def self_contacts(
    world: WorldCore,
    obj: WorldObject,
    pairs: Iterable[tuple[str, str]],
    distance: float = CONTACT_DISTANCE,
) -> list[tuple[str, str]]:
    """The ``(link, link)`` pairs of ``obj`` among ``pairs`` nearer than ``distance`` [m].

    Bounds are compared first, so only pairs whose bounds overlap get closest points.
    """
    cid = world.physics_client()
    index = obj.link_index
    bounds: dict[int, tuple[list[float], list[float]]] = {}

    def box(i: int) -> tuple[list[float], list[float]]:
        if i not in bounds:
            low, high = pybullet.getAABB(obj.body_id, i, physicsClientId=cid)
            bounds[i] = ([v - distance for v in low], [v + distance for v in high])
        return bounds[i]

    found = []
    for a, b in pairs:
        ia, ib = index[a], index[b]
        (la, ha), (lb, hb) = box(ia), box(ib)
        if any(la[k] > hb[k] or lb[k] > ha[k] for k in range(3)):
            continue
        if pybullet.getClosestPoints(
            obj.body_id, obj.body_id, distance, linkIndexA=ia, linkIndexB=ib,
            physicsClientId=cid,
        ):  # fmt: skip
            found.append((a, b))
    return found

"""Which links of a body touch other bodies, found through Bullet's broadphase.

Asking Bullet for the closest points of a robot and a whole kitchen (hundreds of links)
costs ~2 ms; a location validator asks that for every candidate stand, and an IK collision
check for every converged configuration. Here each link's bounds (grown by the contact
distance) ask the broadphase which links of other bodies overlap them, and only those
pairs get closest points. What counts as touching is what :mod:`~robocram.world.closest_points`
says: the body's carried objects and itself never do.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.world.closest_points import CONTACT_DISTANCE, _carried_with, _link_names
from robocram.world.obstacle_boxes import ObstacleBoxes
from robocram.world.pybullet_backend import pybullet
from robocram.world.table_contacts import (
    Bounds,
    bounds_of,
    box_table,
    read_boxes,
    table_contacts,
    table_distances,
)
from robocram.world.world_object import WorldObject

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade

SELF_QUERY = 1e-6  # [m] least distance asked of two links of one body: asked for 0, Bullet
# reports no points for links of one body that penetrate (a 6.6 mm deep HSR finger in its
# base), so touching is asked a hair farther and the distance compared


def link_bounds(world: WorldFacade, obj: WorldObject, indices: Iterable[int]) -> dict[int, Bounds]:
    """The bounds of ``obj``'s links ``indices`` (pybullet link indices) as they are now.

    Queries about one configuration share them (pass them as ``bounds``): a check asks
    both what its links touch and which pairs of its own links touch.
    """
    cid = world.physics.client()
    return {i: pybullet.getAABB(*obj.locate(i), physicsClientId=cid) for i in indices}


def _overlaps(
    world: WorldFacade,
    obj: WorldObject,
    links: Iterable[str] | None,
    skip: set[str],
    distance: float,
    obstacles: ObstacleBoxes | None = None,
    bounds: Mapping[int, Bounds] | None = None,
    kept: ObstacleBoxes | None = None,
) -> Iterator[tuple[str, WorldObject, int, int, str]]:
    """``(link of obj, other object, other's link index, obj's link index, other's link
    name)`` per pair of links whose bounds, grown by ``distance``, overlap; objects named in
    ``skip`` left out. ``obstacles``, when it covers the query, stands in for the
    broadphase; ``bounds`` holds links' bounds read before (:func:`link_bounds`). ``kept``
    bounds covering the query only spare the broadphase the links they find near nothing:
    the others are asked as before, so the pairs come in the broadphase's order."""
    cid = world.physics.client()
    names = _link_names(obj)
    indices = _asked(obj, links)
    if obstacles is not None and obstacles.covers(obj, skip):
        yield from _overlaps_in(obstacles, obj, indices, names, skip, distance, bounds, cid)
        return
    by_body = {b: o for o in world.objects() if o.name not in skip for b in o.bodies}
    other_names: dict[int, dict[int, str]] = {}
    near = _near_somewhere(obj, indices, skip, distance, kept, bounds, cid)
    for index, link in indices.items():
        if near is not None and index not in near:
            continue  # its bounds meet no other's: the broadphase would find nothing near
        low, high = bounds_of(obj, index, bounds, cid)
        if distance:  # IK checks ask for touching: their bounds as read
            low = [v - distance for v in low]
            high = [v + distance for v in high]
        for body, other_link in (
            pybullet.getOverlappingObjects(low, high, physicsClientId=cid) or ()
        ):
            other = by_body.get(body)
            if other is not None:
                if other.body_id not in other_names:
                    other_names[other.body_id] = _link_names(other)
                other_slot = other.slot(body, other_link)
                other_name = other_names[other.body_id].get(other_slot, other.name)
                yield names.get(index, link), other, other_slot, index, other_name


def _asked(obj: WorldObject, links: Iterable[str] | None) -> dict[int, str]:
    """Index -> name of the links of ``obj`` a query asks about that have shapes (all
    of them for None: no shape, no hit)."""
    if links is None:
        return obj.collider_names()
    if isinstance(links, tuple):  # asked again and again by a motion's checks: kept
        return obj.colliders_among(links)
    asked = {obj.link_index[name]: name for name in links}
    return {i: name for i, name in asked.items() if i in obj.colliders}


def _near_somewhere(
    obj: WorldObject,
    indices: dict[int, str],
    skip: set[str],
    distance: float,
    kept: ObstacleBoxes | None,
    bounds: Mapping[int, Bounds] | None,
    cid: int,
) -> set[int] | None:
    """The link indices whose bounds (grown by ``distance``) meet a link of ``kept``'s
    table; None when there is no table covering the query (every link is asked)."""
    if kept is None or not kept.covers(obj, skip):
        return None
    near = _overlaps_in(kept, obj, indices, {}, skip, distance, bounds, cid)
    return {index for _, _, _, index, _ in near}


def _overlaps_in(
    obstacles: ObstacleBoxes,
    obj: WorldObject,
    indices: dict[int, str],
    names: dict[int, str],
    skip: set[str],
    distance: float,
    bounds: Mapping[int, Bounds] | None,
    cid: int,
) -> Iterator[tuple[str, WorldObject, int, int, str]]:
    """:func:`_overlaps` against bounds read before (one comparison for all links)."""
    order = list(indices.items())
    boxes = read_boxes(obj, order, bounds, cid)
    for box, row in obstacles.overlapping(boxes[:, 0] - distance, boxes[:, 1] + distance, skip):
        index, link = order[box]
        yield (
            names.get(index, link), obstacles.objects[row], obstacles.indices[row], index,
            obstacles.names[row],
        )  # fmt: skip


def _near(world: WorldFacade, a: WorldObject, b: WorldObject, la: int, lb: int, d: float) -> bool:
    return bool(_closest(world, a, b, la, lb, d))


def _closest(
    world: WorldFacade, a: WorldObject, b: WorldObject, la: int, lb: int, d: float
) -> list[float]:
    """The distances [m] of Bullet's closest points of link slot ``la`` of ``a`` and
    ``lb`` of ``b`` within ``d`` (none: farther)."""
    (body_a, index_a), (body_b, index_b) = a.locate(la), b.locate(lb)
    points = pybullet.getClosestPoints(
        body_a, body_b, d, linkIndexA=index_a, linkIndexB=index_b,
        physicsClientId=world.physics.client(),
    )  # fmt: skip
    return [float(p[8]) for p in points or ()]


def link_contacts(
    world: WorldFacade,
    obj: WorldObject,
    links: Iterable[str] | None = None,
    ignore: Iterable[WorldObject] = (),
    distance: float = CONTACT_DISTANCE,
) -> list[tuple[str, str]]:
    """``(link of obj, other object)`` pairs nearer than ``distance`` [m], each once (in
    no promised order: callers read them as a set).

    ``links`` limits the links of ``obj`` asked about (default: all of them).
    """
    skip = _carried_with(world, obj) | {o.name for o in ignore}
    boxes = world.contacts.obstacle_boxes(skip)  # kept while the others stay: one comparison
    found: dict[tuple[str, str], None] = {}
    for link, other, other_link, index, _ in _overlaps(world, obj, links, skip, distance, boxes):
        if (link, other.name) not in found and _near(
            world, obj, other, index, other_link, distance
        ):
            found[(link, other.name)] = None
    return list(found)


def link_pairs_in_contact(
    world: WorldFacade,
    obj: WorldObject,
    ignore: Iterable[WorldObject] = (),
    distance: float = CONTACT_DISTANCE,
    links: Iterable[str] | None = None,
    obstacles: ObstacleBoxes | None = None,
    bounds: Mapping[int, Bounds] | None = None,
    kept: ObstacleBoxes | None = None,
) -> list[tuple[str, WorldObject, str]]:
    """``(link of obj, other object, its link)`` triples nearer than ``distance`` [m], each once.

    Unlike :func:`link_contacts` nothing is skipped for being carried: the caller says in
    ``ignore`` what may touch (a robot and what it holds, the floor). ``bounds``: links'
    bounds read before at this configuration (:func:`link_bounds`); others are read here.
    ``kept``: bounds of the others read since they last moved, to skip the links near
    nothing (the answer and its order as without).
    """
    skip = {obj.name} | {o.name for o in ignore}
    if obstacles is not None and obstacles.covers(obj, skip):
        return table_contacts(world, obj, _asked(obj, links), skip, distance, obstacles, bounds)
    found: dict[tuple[str, str, str], tuple[str, WorldObject, str]] = {}
    overlaps = _overlaps(world, obj, links, skip, distance, obstacles, bounds, kept)
    for link, other, other_link, index, other_name in overlaps:
        key = (link, other.name, other_name)
        if key not in found and _near(world, obj, other, index, other_link, distance):
            found[key] = (link, other, other_name)
    return list(found.values())


def link_distances(
    world: WorldFacade,
    obj: WorldObject,
    ignore: Iterable[WorldObject] = (),
    distance: float = CONTACT_DISTANCE,
    links: Iterable[str] | None = None,
    obstacles: ObstacleBoxes | None = None,
) -> list[tuple[str, WorldObject, str, float]]:
    """``(link of obj, other object, its link, distance [m])`` for each pair of links
    nearer than ``distance``, with the smallest distance between them (negative when they
    penetrate). ``links`` limits the links of ``obj`` asked about (default: all)."""
    skip = {obj.name} | {o.name for o in ignore}
    if obstacles is not None and obstacles.covers(obj, skip):
        return table_distances(world, obj, _asked(obj, links), skip, distance, obstacles)
    found: dict[tuple[str, str, str], tuple[str, WorldObject, str, float]] = {}
    overlaps = _overlaps(world, obj, links, skip, distance, obstacles)
    for link, other, other_link, index, other_name in overlaps:
        points = _closest(world, obj, other, index, other_link, distance)
        if not points:
            continue
        nearest = min(points)
        key = (link, other.name, other_name)
        if key not in found or nearest < found[key][3]:
            found[key] = (link, other, other_name, nearest)
    return list(found.values())


def self_contacts(
    world: WorldFacade,
    obj: WorldObject,
    pairs: Iterable[tuple[str, str]],
    distance: float = CONTACT_DISTANCE,
    bounds: Mapping[int, Bounds] | None = None,
) -> list[tuple[str, str]]:
    """The ``(link, link)`` pairs of ``obj`` among ``pairs`` nearer than ``distance`` [m].

    Bounds are compared first (every two links used at once), so only pairs whose bounds
    overlap get closest points; the pairs' rows are kept with ``obj`` per set of pairs.
    ``bounds``: links' bounds read before at this configuration (:func:`link_bounds`).
    """
    key = tuple(pairs)
    if not key:
        return []
    cid = world.physics.client()
    rows = obj.pair_rows(key)
    boxes = [bounds_of(obj, i, bounds, cid) for i in rows.used]
    table = box_table(boxes)
    low, high = table[:, 0] - distance, table[:, 1] + distance
    below = (low[:, None, :] <= high[None, :, :]).all(axis=2)  # [i, j]: i's low under j's
    found = []
    ask = max(distance, SELF_QUERY)
    for k in np.flatnonzero((below & below.T).ravel()[rows.cells]).tolist():
        points = _closest(world, obj, obj, int(rows.firsts[k]), int(rows.seconds[k]), ask)
        if points and min(points) <= distance:
            found.append(key[k])
    return found


def self_distances(
    world: WorldFacade,
    obj: WorldObject,
    pairs: Sequence[tuple[str, str]],
    reach: float,
    exact: Callable[[NDArray[np.float64]], Iterable[int]] | None = None,
) -> NDArray[np.float64]:
    """Per pair of ``obj``'s own links in ``pairs``: a lower bound [m] on the distance
    between the two links, exact (negative: they penetrate that deep) where their bounds
    come within ``reach`` (or, given ``exact``, for the pairs it picks from the bounds'
    gaps, in its order); the other pairs get the distance between their bounds.

    A conservative walk steps by these: a far pair's box gap lets it take long steps
    without any closest-point query.
    """
    gaps = np.zeros(len(pairs))
    if not pairs:
        return gaps
    cid = world.physics.client()
    rows = obj.pair_rows(tuple(pairs))
    boxes = [pybullet.getAABB(*obj.locate(i), physicsClientId=cid) for i in rows.used]
    table = box_table(boxes)
    first = np.searchsorted(rows.used, rows.firsts)
    second = np.searchsorted(rows.used, rows.seconds)
    apart = np.maximum(
        table[first, 0] - table[second, 1], table[second, 0] - table[first, 1]
    )  # (pairs, 3): per axis, how far the boxes are apart (<= 0: they overlap on it)
    gaps[:] = np.sqrt((np.maximum(apart, 0.0) ** 2).sum(axis=1))
    picked = np.flatnonzero(gaps <= reach).tolist() if exact is None else exact(gaps)
    for k in picked:
        points = _closest(
            world, obj, obj, int(rows.firsts[k]), int(rows.seconds[k]), max(reach, SELF_QUERY)
        )
        far = np.nextafter(max(gaps[k], reach), np.inf)  # no points: farther than reach
        gaps[k] = min(points) if points else far
    return gaps

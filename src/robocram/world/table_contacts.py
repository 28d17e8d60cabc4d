"""Contact and distance queries of a body's links answered from a kept obstacle table.

A motion's checks ask, tens of times per segment, which links of the robot are near what:
the others' bounds are kept in one table (:class:`~robocram.world.obstacle_boxes.ObstacleBoxes`)
while only the robot moves, so one comparison finds the overlapping pairs and each pair
is asked of Bullet directly, in one loop (the general path's generators and per-pair
calls cost about as much as Bullet's answers). The pairs, their order and every Bullet
call's arguments are those of :mod:`~robocram.world.link_contacts`' general path.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from itertools import chain
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.world.closest_points import _link_names
from robocram.world.obstacle_boxes import ObstacleBoxes
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_object import WorldObject

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade

Bounds = tuple[Sequence[float], Sequence[float]]  # a link's (low, high) corners [m]


def box_table(boxes: Sequence[Bounds]) -> NDArray[np.float64]:
    """``boxes`` as a (boxes, 2, 3) array of their low and high corners [m]: read flat
    (the same floats; numpy's nested-sequence discovery cost more than the query)."""
    flat = chain.from_iterable
    return np.fromiter(flat(flat(boxes)), dtype=float, count=6 * len(boxes)).reshape(-1, 2, 3)


def bounds_of(
    obj: WorldObject, index: int, bounds: Mapping[int, Bounds] | None, cid: int
) -> Bounds:
    """Link slot ``index``'s bounds: from ``bounds`` (read before at this configuration)
    when there, else read now."""
    if bounds is not None:
        found = bounds.get(index)
        if found is not None:
            return found
    return pybullet.getAABB(*obj.locate(index), physicsClientId=cid)


def read_boxes(
    obj: WorldObject,
    order: Sequence[tuple[int, str]],
    bounds: Mapping[int, Bounds] | None,
    cid: int,
) -> NDArray[np.float64]:
    """The bounds of ``order``'s link slots as a :func:`box_table`: from ``bounds`` where
    read before, else from Bullet (one body, nothing read before: asked directly)."""
    if bounds is None and not obj.parts:
        body, aabb = obj.body_id, pybullet.getAABB
        return box_table([aabb(body, index, physicsClientId=cid) for index, _ in order])
    return box_table([bounds_of(obj, index, bounds, cid) for index, _ in order])


def _table_hits(
    obj: WorldObject,
    indices: dict[int, str],
    skip: set[str],
    distance: float,
    obstacles: ObstacleBoxes,
    bounds: Mapping[int, Bounds] | None,
    cid: int,
) -> list[tuple[int, str, int]]:
    """``(link index, link name asked, table row)`` per overlapping pair, in the general
    path's order, the links' bounds read as it reads them."""
    order = list(indices.items())
    boxes = read_boxes(obj, order, bounds, cid)
    low, high = boxes[:, 0] - distance, boxes[:, 1] + distance
    return [(*order[box], row) for box, row in obstacles.overlapping(low, high, skip)]


def table_distances(
    world: WorldFacade,
    obj: WorldObject,
    indices: dict[int, str],
    skip: set[str],
    distance: float,
    obstacles: ObstacleBoxes,
) -> list[tuple[str, WorldObject, str, float]]:
    """:func:`~robocram.world.link_contacts.link_distances` where ``obstacles`` covers
    the query: the same pairs asked in the same order with the same arguments, in one
    loop (a motion's walk asks this at every check)."""
    cid = world.physics.client()
    names = _link_names(obj)
    closest = pybullet.getClosestPoints
    objects, others, other_names = obstacles.objects, obstacles.indices, obstacles.names
    found: dict[tuple[str, str, str], tuple[str, WorldObject, str, float]] = {}
    for index, link, row in _table_hits(obj, indices, skip, distance, obstacles, None, cid):
        other = objects[row]
        (body_a, index_a), (body_b, index_b) = obj.locate(index), other.locate(others[row])
        points = closest(
            body_a, body_b, distance, linkIndexA=index_a, linkIndexB=index_b,
            physicsClientId=cid,
        )  # fmt: skip
        if not points:
            continue
        nearest = min([float(p[8]) for p in points])
        name, other_name = names.get(index, link), other_names[row]
        key = (name, other.name, other_name)
        kept = found.get(key)
        if kept is None or nearest < kept[3]:
            found[key] = (name, other, other_name, nearest)
    return list(found.values())


def table_contacts(
    world: WorldFacade,
    obj: WorldObject,
    indices: dict[int, str],
    skip: set[str],
    distance: float,
    obstacles: ObstacleBoxes,
    bounds: Mapping[int, Bounds] | None,
) -> list[tuple[str, WorldObject, str]]:
    """:func:`~robocram.world.link_contacts.link_pairs_in_contact` where ``obstacles``
    covers the query, in one loop: the same pairs, one already found not asked again."""
    cid = world.physics.client()
    names = _link_names(obj)
    closest = pybullet.getClosestPoints
    objects, others, other_names = obstacles.objects, obstacles.indices, obstacles.names
    found: dict[tuple[str, str, str], tuple[str, WorldObject, str]] = {}
    for index, link, row in _table_hits(obj, indices, skip, distance, obstacles, bounds, cid):
        other = objects[row]
        name, other_name = names.get(index, link), other_names[row]
        key = (name, other.name, other_name)
        if key in found:
            continue
        (body_a, index_a), (body_b, index_b) = obj.locate(index), other.locate(others[row])
        if closest(
            body_a, body_b, distance, linkIndexA=index_a, linkIndexB=index_b,
            physicsClientId=cid,
        ):  # fmt: skip
            found[key] = (name, other, other_name)
    return list(found.values())

"""``on`` and ``in_``: where an object fits on a supporting surface or inside a container.

Rays cast straight down over the grid find the support's top (or the container's inner
bottom) cell by cell; cells where something else is hit first are taken. The free cells
are then shrunk by the margin plus the placed object's footprint radius, so the object
fits, and each cell's height is set so the object's bottom rests on the surface.

Inside a container, cells open from above (the part of an opened drawer out of its
cabinet) weigh :data:`OPEN_ABOVE` times as much as those under a top or a shelf: a hand
puts things down from above there, and a spot under the counter has no stand. A container
with no cell open above (a fridge's shelf) weighs all its cells alike.

Inside a container the radius is the object's outline about its frame
(:func:`~robocram.world.footprint.footprint_radius`: a bowl needs its own 8 cm circle, so
two fit side by side in a drawer); on a surface it is still its bounds' half diagonal
(11.5 cm for the bowl), which keeps every placing on counters and tables as it was.

``see_through`` (a name or names, e.g. the robot asking) makes the rays go on past those
bodies and what they hold: a robot standing at a table with a second thing in its other
hand is not an obstacle on the table, as a person choosing a free spot ignores their own
arm. Without it every body counts.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.costmaps.cost_layer import CostLayer, LocationQuery
from robocram.costmaps.grid import BoolGrid, erode
from robocram.costmaps.out_of_the_way import out_of_the_way
from robocram.world import World, WorldObject
from robocram.world.footprint import footprint_radius
from robocram.world.ray_hit import RayHits, ray_hits, ray_hits_past

SURFACE_MARGIN = 0.03  # [m] kept free between the placed object and the support's edges
INNER_DEPTH = 0.02  # [m] an inside bottom lies at least this far below a container's rim
FLAT = 0.9  # a hit counts as a surface if its normal's z is at least this
RESTING_GAP = 0.002  # [m] the object is put this far above the surface
BOTTOM_RAYS = 7  # rays per side of the grid that finds a placed object's bottom
OPEN_ABOVE = 20.0  # how much more a cell inside a container weighs when open from above
ABOVE = 0.5  # [m] over a support's top, where rays down start (nothing stands that high on it)


def _placed(query: LocationQuery, inside: bool) -> tuple[WorldObject | None, float]:
    """The ``for_`` object and its footprint radius [m] (its outline ``inside`` a container)."""
    value = query.designator.get("for_")
    if value is None:
        return None, 0.0
    obj = query.object(value, "for_")
    if inside:
        return obj, footprint_radius(query.world, obj)
    low, high = query.world.aabb(obj)
    return obj, math.hypot(high[0] - low[0], high[1] - low[1]) / 2


def _frame_over_bottom(world: World, obj: WorldObject | None) -> float:
    """How far [m] ``obj``'s frame is above its lowest point, by rays cast up at it.

    Its bounds would say a few millimetres more (Bullet grows them by its collision
    margin), and an object put down that much too high falls that far when let go, which
    the settling check then waits out. Asked while the object is out of the way, so the
    rays meet nothing else; the bounds' answer stands when no ray hits.
    """
    if obj is None:
        return 0.0
    low, high = world.aabb(obj)
    xs = np.linspace(low[0], high[0], BOTTOM_RAYS + 2)[1:-1]
    ys = np.linspace(low[1], high[1], BOTTOM_RAYS + 2)[1:-1]
    gx, gy = np.meshgrid(xs, ys)
    starts = np.column_stack([gx.ravel(), gy.ravel(), np.full(gx.size, low[2] - 0.05)])
    ends = starts.copy()
    ends[:, 2] = high[2] + 0.05
    hits = ray_hits(world, starts, ends)
    on_it = hits.bodies == obj.body_id
    bottom = float(hits.positions[on_it, 2].min()) if on_it.any() else low[2]
    return world.pose(obj).position[2] - bottom


def seen_through(query: LocationQuery) -> list[WorldObject]:
    """The bodies the ``see_through`` key names, and everything they hold."""
    value = query.designator.get("see_through")
    if value is None:
        return []
    names = list(value) if isinstance(value, list | tuple) else [value]
    bodies = [query.object(name, "see_through") for name in names]
    held = [query.world.object(n) for b in bodies for n in query.world.bodies.attachments(b)]
    return list(dict.fromkeys(bodies + held))


def _down(world: World, starts: np.ndarray, ends: np.ndarray, past: list[WorldObject]) -> RayHits:
    """The rays' first hits, past the bodies ``past`` (if any)."""
    if not past:
        return ray_hits(world, starts, ends)
    ids = np.array([obj.body_id for obj in past], dtype=np.int64)
    return ray_hits_past(world, starts, ends, ids)


def _surface(query: LocationQuery, value: object, key: str, alive: BoolGrid) -> CostLayer:
    world, inside = query.world, key == "in_"
    support, link = query.part(value, key)
    low, high = query.bounds(value, key)
    placed, radius = _placed(query, inside)
    x, y = query.centres()
    over = (x >= low[0]) & (x <= high[0]) & (y >= low[1]) & (y <= high[1])
    rows, cols = np.nonzero(alive & over)  # a ray straight down elsewhere cannot meet it
    top = high[2] - 0.01 if inside else high[2] + ABOVE
    starts = np.column_stack([x[rows, cols], y[rows, cols], np.full(len(rows), top)])
    ends = starts.copy()
    ends[:, 2] = low[2] - 0.01
    with out_of_the_way(world, [placed]):
        hits = _down(world, starts, ends, seen_through(query))
        lift = _frame_over_bottom(world, placed)
    ok = (hits.bodies == support.body_id) & (hits.normals[:, 2] >= FLAT)
    if link is not None:
        ok &= hits.links == support.link_index[link]
    if inside:
        ok &= hits.positions[:, 2] <= high[2] - INNER_DEPTH
    heights = np.zeros(query.grid.shape)
    free = np.zeros(query.grid.shape, dtype=bool)
    free[rows[ok], cols[ok]] = True
    heights[rows[ok], cols[ok]] = hits.positions[ok, 2] + lift + RESTING_GAP
    fits = erode(free, (SURFACE_MARGIN + radius) / query.grid.resolution).astype(float)
    if inside and ok.any():
        with out_of_the_way(world, [placed]):
            open_ = _open_above(world, support, link, starts[ok, :2], high[2])
        fits[rows[ok][open_], cols[ok][open_]] *= OPEN_ABOVE
    return CostLayer(fits, heights=heights)


def _open_above(
    world: World, support: WorldObject, link: str | None, points: np.ndarray, top: float
) -> np.ndarray:
    """Per map point (x, y) inside a container whose top is at ``top`` [m]: whether a ray
    down from :data:`ABOVE` over it meets the container's inside first (nothing covers it)."""
    starts = np.column_stack([points, np.full(len(points), top + ABOVE)])
    ends = np.column_stack([points, np.full(len(points), top - 1.0)])
    hits = ray_hits(world, starts, ends)
    found = hits.bodies == support.body_id
    if link is not None:
        found &= hits.links == support.link_index[link]
    return np.asarray(found)


def on_cost(query: LocationQuery, value: object, alive: BoolGrid) -> CostLayer:
    """``on=support`` (an object or ``(object, link)``): where the ``for_`` object fits."""
    return _surface(query, value, "on", alive)


def in_cost(query: LocationQuery, value: object, alive: BoolGrid) -> CostLayer:
    """``in_=container`` (e.g. ``(kitchen, drawer link)``): its inner bottom, where it fits."""
    return _surface(query, value, "in_", alive)

"""How far an object reaches out from its vertical axis: the circle it needs on a surface.

A costmap that puts an object somewhere keeps its cells this far from edges and other
things. The bounds' half diagonal over-states it for a round thing (a 16 cm bowl needs an
8 cm circle; its bounds say 11.5 cm), so a drawer that holds two bowls side by side would
have no room for the second. Horizontal rays cast at the body alone
(:mod:`~robocram.world.shape_rays`, nothing else in the way), towards the vertical axis
through its frame, from every side and at several heights, find its outline; the farthest
hit is the radius. Where its shapes are not modelled there (planes, STL meshes), the
farthest corner of its bounds from that axis stands.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.world.shape_rays import lone_body
from robocram.world.world import World
from robocram.world.world_object import WorldObject

FOOTPRINT_TURNS = 72  # rays round the axis per height: 5 degrees apart
FOOTPRINT_LEVELS = 8  # heights between the body's bottom and top
FOOTPRINT_SLACK = 0.002  # [m] added: a corner between two rays reaches this little farther


def bounds_radius(world: World, obj: WorldObject) -> float:
    """The farthest corner [m] of ``obj``'s world-aligned bounds from its frame's vertical
    axis: a circle that surely holds it seen from above."""
    low, high = world.aabb(obj)
    x, y, _ = world.pose(obj).position
    return math.hypot(max(x - low[0], high[0] - x), max(y - low[1], high[1] - y))


def footprint_radius(world: World, obj: WorldObject) -> float:
    """The radius [m] about ``obj``'s frame's vertical axis of the circle its shapes fill
    seen from above (within :data:`FOOTPRINT_SLACK`), as it stands now."""
    outer = bounds_radius(world, obj)
    lone = lone_body(world, obj)
    if lone is None:
        return outer
    low, high = world.aabb(obj)
    x, y, _ = world.pose(obj).position
    start = outer + 0.01  # [m] rays start outside the body
    turns = np.linspace(0.0, 2 * math.pi, FOOTPRINT_TURNS, endpoint=False)
    heights = np.linspace(low[2], high[2], FOOTPRINT_LEVELS + 2)[1:-1]
    turn, height = (a.ravel() for a in np.meshgrid(turns, heights))
    out = np.column_stack([np.cos(turn), np.sin(turn), np.zeros_like(turn)])
    origins = np.column_stack([x + start * out[:, 0], y + start * out[:, 1], height])
    hits = lone.first_hit(origins, -out, np.full(len(turn), start))
    met = np.isfinite(hits)
    if not met.any():
        return outer
    return min(float(start - hits[met].min()) + FOOTPRINT_SLACK, outer)

"""What a cost function gets (a :class:`LocationQuery`) and gives back (a :class:`CostLayer`).

A cost function is ``fn(query, value, alive) -> CostLayer``: ``value`` is the designator
key's value, ``alive`` the cells earlier layers left possible (cells outside it may be
given anything, so expensive functions evaluate only those). A layer may also set the
height of a pose (a table top) and its yaw (turn the base so an arm faces the target).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.grid import BoolGrid, CostmapGrid, FloatGrid
from robocram.costmaps.location_blame import LocationBlame
from robocram.costmaps.reachability_map import ReachabilityMaps
from robocram.designators import ObjectDesignator
from robocram.logic import Value
from robocram.tf import Pose, PoseStamped, Vector3
from robocram.world import RobotObject, World, WorldObject

CellRefiner = Callable[[NDArray[np.int64]], FloatGrid]


@dataclass(frozen=True, eq=False)
class CostLayer:
    """Weights (>= 0) over the grid, and optionally heights [m] and yaws [rad] of poses.

    An expensive layer may leave part of its work for later: ``refine`` maps cells
    (K x 2 ``[row, column]``) to factors in 0..1 that multiply ``weights``. A whole costmap
    (for a picture) applies it everywhere; a pose stream applies it only to the cells it
    draws, keeping each with that probability, which samples the same product lazily.
    """

    weights: FloatGrid
    heights: FloatGrid | None = None
    yaws: FloatGrid | None = None
    refine: CellRefiner | None = None


@dataclass(frozen=True, eq=False)
class LocationQuery:
    """The world, the designator being resolved, its grid and the robot it is for."""

    world: World
    designator: Any
    grid: CostmapGrid
    robot: RobotObject | None
    reach_maps: ReachabilityMaps = field(default_factory=ReachabilityMaps)
    memo: dict[object, object] = field(default_factory=dict, repr=False)  # per resolution: what
    # validators work out once for all candidates (an object's shape, its grasp names)
    blame: LocationBlame = field(default_factory=LocationBlame, repr=False)  # per resolution:
    # the objects refused candidates failed on (recorded only when one is refused)

    def centres(self) -> tuple[FloatGrid, FloatGrid]:
        """Map x and y [m] of the cell centres."""
        return self.grid.centres()

    def object(self, value: object, key: str) -> WorldObject:
        """The world object ``value`` names (a name, an object, an object designator)."""
        return resolve_object(self.world, value, key)

    def part(self, value: Value, key: str) -> tuple[WorldObject, str | None]:
        """The object and link ``value`` names: an object, or ``(object, link)`` for a part
        of an articulated one such as ``("kitchen", "drawer_unit_drawer_3")``."""
        if isinstance(value, tuple) and len(value) == 2 and isinstance(value[1], str):
            obj = self.object(value[0], key)
            if value[1] not in self.world.link_names(obj):
                raise CostmapInputError(
                    f"location key {key!r} names link {value[1]!r}, which {obj.name!r} does "
                    f"not have; its links: {', '.join(self.world.link_names(obj)[:12])}...",
                    value[1],
                )
            return obj, value[1]
        return self.object(value, key), None

    def bounds(self, value: Value, key: str) -> tuple[Vector3, Vector3]:
        """World-aligned bounds [m] of the object or ``(object, link)`` ``value`` names."""
        obj, link = self.part(value, key)
        return self.world.aabb(obj) if link is None else self.world.contacts.link_aabb(obj, link)

    def point(self, value: Value, key: str) -> tuple[float, float, float]:
        """Map (x, y, z) [m] of a pose, a point, or the centre of an object's (link's) bounds."""
        if isinstance(value, Pose | PoseStamped):
            return Pose.coerce(value.pose if isinstance(value, PoseStamped) else value).position
        if isinstance(value, tuple) and len(value) == 3:
            return (float(value[0]), float(value[1]), float(value[2]))
        low, high = self.bounds(value, key)
        return ((low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2)


def resolve_object(world: World, value: object, key: str) -> WorldObject:
    """The world object ``value`` stands for; a typed error naming ``key`` otherwise."""
    name = value
    if isinstance(value, ObjectDesignator):
        name = value.get("name")
    if isinstance(value, WorldObject):
        name = value.name
    if not isinstance(name, str):
        raise CostmapInputError(
            f"location key {key!r} needs an object in the world (a name or a WorldObject), "
            f"got {value!r}",
            value,
        )
    if name not in world:
        known = ", ".join(o.name for o in world.objects())
        raise CostmapInputError(
            f"location key {key!r} names object {name!r}, which is not in the world "
            f"(objects: {known}); add it first or fix the name",
            name,
        )
    return world.object(name)


CostFunction = Callable[[LocationQuery, Value, BoolGrid], CostLayer]


def ones(query: LocationQuery) -> FloatGrid:
    """A layer that rules nothing out."""
    return np.ones(query.grid.shape)

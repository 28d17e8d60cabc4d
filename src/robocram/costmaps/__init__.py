"""Costmaps: where to stand to see, to reach, and where to put things.

A location designator such as ``a.location(visible_for="boxy", object=pot)`` is resolved
by :class:`CostmapLocations`: rules in the knowledge base map its keys to cost functions,
whose normalised product (a :class:`Costmap`) is sampled lazily into poses that
validators check in the world. Bind it with ``using_location_resolver(locs.resolver())``;
``simulated_robot`` binds one by default.
"""

from robocram.costmaps.cost_layer import CostFunction, CostLayer, LocationQuery
from robocram.costmaps.costmap import Costmap
from robocram.costmaps.costmap_locations import CostmapLocations
from robocram.costmaps.costmap_observers import CostmapObserver, notify_costmap, observing_costmaps
from robocram.costmaps.distance_costs import gaussian, ring
from robocram.costmaps.errors import (
    CostmapError,
    CostmapInputError,
    CostmapUsageError,
    LocationKeyError,
    LocationNotFound,
    LocationOutsideArea,
)
from robocram.costmaps.grid import CostmapGrid
from robocram.costmaps.reach_reasoning import (
    blocking,
    install_reach_predicates,
    pose_reachable,
    reachable,
)
from robocram.costmaps.reachability_map import (
    ReachabilityMap,
    ReachabilityMaps,
    build_reachability_map,
)
from robocram.costmaps.stand_reach import reach_to_pick, reach_to_place
from robocram.costmaps.validators import Reach, reach_object
from robocram.robots.disk_cache import cache_dir

__all__ = [
    "CostFunction",
    "CostLayer",
    "Costmap",
    "CostmapError",
    "CostmapGrid",
    "CostmapInputError",
    "CostmapLocations",
    "CostmapObserver",
    "CostmapUsageError",
    "LocationKeyError",
    "LocationNotFound",
    "LocationOutsideArea",
    "LocationQuery",
    "Reach",
    "ReachabilityMap",
    "ReachabilityMaps",
    "blocking",
    "build_reachability_map",
    "cache_dir",
    "gaussian",
    "install_reach_predicates",
    "notify_costmap",
    "observing_costmaps",
    "pose_reachable",
    "reach_object",
    "reach_to_pick",
    "reach_to_place",
    "reachable",
    "ring",
]

"""The cost functions and validators ``location_keys.pl`` names, by name (copied into each
locator)."""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from robocram.costmaps.cost_layer import CostFunction
from robocram.costmaps.distance_costs import at_cost, near_cost
from robocram.costmaps.occupancy import occupancy_cost
from robocram.costmaps.reachability_cost import reachability_cost
from robocram.costmaps.relation_costs import (
    behind_cost,
    in_front_of_cost,
    left_of_cost,
    right_of_cost,
)
from robocram.costmaps.stand_reach import reachable
from robocram.costmaps.surface_costs import in_cost, on_cost
from robocram.costmaps.validators import (
    Validator,
    object_collision_free,
    robot_collision_free,
    visible,
)
from robocram.costmaps.visibility_cost import visibility_cost

BUILTIN_COST_FUNCTIONS: Mapping[str, CostFunction] = MappingProxyType(
    {
        "at": at_cost,
        "behind": behind_cost,
        "in_front_of": in_front_of_cost,
        "inside": in_cost,
        "left_of": left_of_cost,
        "near": near_cost,
        "occupancy": occupancy_cost,
        "on": on_cost,
        "reachability": reachability_cost,
        "right_of": right_of_cost,
        "visibility": visibility_cost,
    }
)

BUILTIN_VALIDATORS: Mapping[str, Validator] = MappingProxyType(
    {
        "object_collision_free": object_collision_free,
        "reachable": reachable,
        "robot_collision_free": robot_collision_free,
        "visible": visible,
    }
)

"""``left_of``, ``right_of``, ``in_front_of``, ``behind``: sides of a reference object.

Sides are seen from the robot, as a person would say them: "in front of" is the side of
the reference facing the robot, "left of" the robot's left when it faces the reference.
Without a robot the map's x axis is the line of sight. Weight grows with how squarely a
cell lies on the side and fades to 0 at 1 m from the reference's bounds.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from robocram.costmaps.cost_layer import CostLayer, LocationQuery
from robocram.costmaps.distance_costs import near_cost
from robocram.costmaps.grid import BoolGrid

# side -> (forward component, left component) of the wanted direction from the reference
_SIDES: dict[str, tuple[float, float]] = {
    "left_of": (0.0, 1.0),
    "right_of": (0.0, -1.0),
    "in_front_of": (-1.0, 0.0),
    "behind": (1.0, 0.0),
}


def _side_cost(side: str) -> Callable[[LocationQuery, Any, BoolGrid], CostLayer]:
    forward_part, left_part = _SIDES[side]

    def cost(query: LocationQuery, value: object, alive: BoolGrid) -> CostLayer:
        centre = np.array(query.point(value, side)[:2])
        if query.robot is not None:
            sight = centre - np.array(query.world.pose(query.robot).position[:2])
        else:
            sight = np.array((1.0, 0.0))
        norm = float(np.linalg.norm(sight))
        forward = sight / norm if norm > 1e-6 else np.array((1.0, 0.0))
        left = np.array((-forward[1], forward[0]))
        wanted = forward_part * forward + left_part * left
        x, y = query.centres()
        offset = np.stack([x - centre[0], y - centre[1]], axis=-1)
        distance = np.maximum(np.linalg.norm(offset, axis=-1), 1e-9)
        squareness = np.clip((offset @ wanted) / distance, 0.0, 1.0)
        return CostLayer(squareness * near_cost(query, value, alive).weights)

    cost.__name__ = f"{side}_cost"
    cost.__doc__ = f"``{side}=obj``: cells on that side of the object, seen from the robot."
    return cost


left_of_cost = _side_cost("left_of")
right_of_cost = _side_cost("right_of")
in_front_of_cost = _side_cost("in_front_of")
behind_cost = _side_cost("behind")

"""Reachability: cells from which an arm reaches the object, by the inverse reachability map.

For a target at horizontal distance ``d`` and height ``z`` over a cell, each arm's map
gives how well it reaches and at which bearing in the base the target should lie. A cell
takes its best arm's score, and its yaw turns the base so that arm faces the target.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from robocram.costmaps.cost_layer import CostLayer, LocationQuery
from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.grasps import grasp_point
from robocram.costmaps.grid import BoolGrid


def reachability_cost(query: LocationQuery, value: Any, alive: BoolGrid) -> CostLayer:
    """Best arm's reach score per cell, with the base yaw that gives it."""
    robot = query.robot
    if robot is None:
        raise CostmapInputError(f"{query.designator.description} names no robot", None)
    desc = robot.description
    arm = query.designator.get("arm")
    arms = [arm] if arm is not None else [a for a in desc.arms if a != desc.neck_arm]
    for name in arms:
        if name not in desc.arms:
            raise CostmapInputError(
                f"robot {robot.name!r} has no arm {name!r}; it has {sorted(desc.arms)}", name
            )
    obj = query.designator.get("object")
    if obj is not None:
        target = grasp_point(query.world, query.object(obj, "object"))
    else:
        target = query.point(query.designator.get("target"), "target")
    height = target[2] - query.world.pose(robot).position[2]
    x, y = query.centres()
    distance = np.hypot(target[0] - x, target[1] - y)
    towards = np.arctan2(target[1] - y, target[0] - x)
    score = np.zeros(query.grid.shape)
    yaws = np.zeros(query.grid.shape)
    for name in arms:
        arm_score, bearing = query.reach_maps.get(desc, name).best(distance, height)
        better = arm_score > score
        score = np.where(better, arm_score, score)
        yaws = np.where(better, towards - bearing, yaws)
    return CostLayer(score, yaws=yaws)

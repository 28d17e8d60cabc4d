"""Reachability: cells from which an arm reaches the object, by the inverse reachability map.

Each arm reaches best along its working direction from its shoulder (straight ahead for
most, the base's -y for Stretch), so a cell's yaw turns the base until the target lies on
that line (the arm faces the target; for an arm of five joints such as the HSR's this is
the only line it reaches from above). The arm's
reachability map then scores the target's place in the base frame; a cell takes the
score of its best arm, squared so that likely cells are drawn first.
"""

from __future__ import annotations

import numpy as np

from robocram.costmaps.cost_layer import CostLayer, LocationQuery
from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.grasps import arm_working_yaw, grasp_point, shoulder_offset
from robocram.costmaps.grid import BoolGrid
from robocram.costmaps.reachability_map import RADIUS_STEP
from robocram.costmaps.validators import robot_arms


def reachability_cost(query: LocationQuery, value: object, alive: BoolGrid) -> CostLayer:
    """Best arm's reach score per cell, with the base yaw that gives it."""
    robot = query.robot
    if robot is None:
        raise CostmapInputError(f"{query.designator.description} names no robot", None)
    desc = robot.description
    arms = robot_arms(robot, query.designator.get("arm"))
    obj = query.designator.get("object")
    if obj is not None:
        target = grasp_point(query.world, query.object(obj, "object"))
    else:
        target = query.point(query.designator.get("target"), "target")
    height = target[2] - query.world.pose(robot).position[2]
    x, y = query.centres()
    distance = np.hypot(target[0] - x, target[1] - y).ravel()
    towards = np.arctan2(target[1] - y, target[0] - x).ravel()
    score = np.zeros(distance.shape)
    yaws = np.zeros(distance.shape)
    for name in arms:
        side = shoulder_offset(desc, name)
        turn_to_work = arm_working_yaw(desc, name)
        reach_map = query.reach_maps.get(desc, name)
        # the map scores 0 beyond its radius at this height: ask only for the cells within
        # (a bin's margin for rounding), whose target is off the shoulder's line
        asked = (distance > abs(side)) & (distance < reach_map.radius_at(height) + RADIUS_STEP)
        ahead = np.sqrt(np.maximum(distance[asked] ** 2 - side**2, 0.0))
        c, s = np.cos(turn_to_work), np.sin(turn_to_work)  # working frame to base frame
        points = np.column_stack(
            [c * ahead - s * side, s * ahead + c * side, np.full_like(ahead, height)]
        )
        arm_score = np.zeros(distance.shape)
        arm_score[asked] = reach_map.scores_at(points)
        better = arm_score > score
        score = np.where(better, arm_score, score)
        turn = np.arcsin(np.clip(side / np.maximum(distance, 1e-9), -1.0, 1.0))
        yaws = np.where(better, towards - turn - turn_to_work, yaws)
    shape = query.grid.shape
    return CostLayer(
        (score**2).reshape(shape), yaws=yaws.reshape(shape)
    )  # squared: likeliest first

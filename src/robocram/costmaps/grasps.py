"""Grasps from above: the tool's approach axis and the tool poses that grasp an object.

The approach axis runs from the wrist (the arm's end-effector link) to the tool frame;
a grasp from above points it straight down over the object's centre, turned about the
vertical (in the robot's base frame) by one of :data:`GRASP_YAWS`.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics import forward_kinematics
from robocram.robots import RobotDescription, load_description
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World, WorldObject

GRASP_HEIGHT = 0.05  # [m] over the object's bottom (at most half its height)
GRASP_YAWS = (0.0, math.pi / 2, math.pi, -math.pi / 2)  # [rad] turns tried in order


def approach_axis(desc: RobotDescription, arm: str) -> NDArray[np.float64]:
    """The unit approach axis of ``arm``'s tool, in the tool frame."""
    spec = desc.arms[arm]
    tool = forward_kinematics(desc, {}, spec.tool_frame)
    wrist = forward_kinematics(desc, {}, spec.end_effector_link)
    axis = -np.asarray((tool.inverse() * wrist).position, dtype=float)
    norm = float(np.linalg.norm(axis))
    return axis / norm if norm > 1e-9 else np.array((0.0, 0.0, 1.0))


def top_down(axis_in_tool: NDArray[np.float64], yaw: float) -> quat.Quaternion:
    """Tool orientation that points ``axis_in_tool`` straight down, turned by ``yaw``."""
    down = np.array((0.0, 0.0, -1.0))
    turn = np.cross(axis_in_tool, down)
    angle = math.atan2(float(np.linalg.norm(turn)), float(axis_in_tool @ down))
    if np.linalg.norm(turn) < 1e-9:
        turn = np.array((1.0, 0.0, 0.0))
    unit = turn / np.linalg.norm(turn)
    aligned = quat.from_axis_angle((float(unit[0]), float(unit[1]), float(unit[2])), angle)
    return quat.multiply(quat.from_euler(0.0, 0.0, yaw), aligned)


def grasp_point(world: World, obj: WorldObject) -> tuple[float, float, float]:
    """Map point [m] a grasp from above closes on: over the centre, near the bottom."""
    low, high = world.aabb(obj)
    z = low[2] + min(GRASP_HEIGHT, (high[2] - low[2]) / 2)
    return ((low[0] + high[0]) / 2, (low[1] + high[1]) / 2, z)


def grasp_poses(
    world: World, obj: WorldObject, desc: RobotDescription, arm: str, base: Pose
) -> list[Pose]:
    """Poses in the base frame of ``arm``'s tool grasping ``obj`` from above, one per yaw.

    The yaws turn the hand relative to the base, not the map: a five-joint arm such as
    the HSR's reaches a grasp from above only in a few headings relative to its base.
    """
    axis = approach_axis(desc, arm)
    point = base.inverse().transform_point(grasp_point(world, obj))
    return [Pose(point, top_down(axis, yaw)) for yaw in GRASP_YAWS]


def shoulder_offset(desc: RobotDescription, arm: str) -> float:
    """Sideways offset [m] (base y) of the arm's first joint: the line it reaches along."""
    model = load_description(desc).model
    first = model.joints[desc.arms[arm].joints[0]] if desc.arms[arm].joints else None
    if first is None:
        return 0.0
    return forward_kinematics(desc, {}, first.child).position[1]

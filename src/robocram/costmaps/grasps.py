"""The grasps the reachability costmap checks: the grasp model's, seen from a base pose.

The costmap and the plans use one grasp model (``robocram.grasping``, docs/grasping.md):
the validator tries the same grasps, best first, that ``pick_up_object`` will, so a pose
it accepts is one the plan can grasp from.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from robocram.grasping import (
    GraspingError,
    Hand,
    ObjectUngraspable,
    candidates_at,
    grasp_names,
    grasps,
    object_shape,
)
from robocram.grasping import (
    approach_axis as tool_approach_axis,
)
from robocram.kinematics import forward_kinematics
from robocram.robots import LoadedDescription, RobotDescription, load_description
from robocram.robots.arm_envelope import working_yaw
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World, WorldObject

ANY_HAND = Hand(max_opening=float("inf"))  # where a grasp from above closes, whatever the hand
GRASP_YAWS = (0.0, math.pi / 2, math.pi, -math.pi / 2)  # [rad] turns of a tool over a point


def approach_axis(desc: RobotDescription, arm: str) -> NDArray[np.float64]:
    """The unit approach axis of ``arm``'s tool, in the tool frame."""
    return np.asarray(tool_approach_axis(desc, arm), dtype=float)


def top_down(axis_in_tool: NDArray[np.float64], yaw: float) -> quat.Quaternion:
    """Tool orientation that points ``axis_in_tool`` straight down, turned by ``yaw``.

    For a tool over a point rather than an object (``reach_point``): with no object there
    is no grasp, only the approach from above of the model's ``top`` grasps.
    """
    down = np.array((0.0, 0.0, -1.0))
    turn = np.cross(axis_in_tool, down)
    angle = math.atan2(float(np.linalg.norm(turn)), float(axis_in_tool @ down))
    if np.linalg.norm(turn) < 1e-9:
        turn = np.array((1.0, 0.0, 0.0))
    unit = turn / np.linalg.norm(turn)
    aligned = quat.from_axis_angle((float(unit[0]), float(unit[1]), float(unit[2])), angle)
    return quat.multiply(quat.from_euler(0.0, 0.0, yaw), aligned)


def grasp_point(world: World, obj: WorldObject) -> tuple[float, float, float]:
    """Map point [m] where a grasp from above closes on ``obj`` (the model's top grasp)."""
    top = grasps(object_shape(world, obj), ANY_HAND, ("top",))[0]
    x, y, z = (world.pose(obj) * top.tool).position
    return (x, y, z)


def grasp_poses(
    world: World, obj: WorldObject, desc: RobotDescription, arm: str, base: Pose
) -> list[Pose]:
    """Tool poses in the base frame of ``arm`` grasping ``obj``, best first.

    The grasps and their order are those the pick-up plan tries (the type's
    ``object_grasps/2``, the hand's width); none when the hand fits no grasp.
    """
    try:
        found = candidates_at(
            object_shape(world, obj),
            world.pose(obj),
            desc,
            arm,
            base,
            grasp_names(world.kb, obj.type),
        )
    except (ObjectUngraspable, GraspingError):
        return []
    inverse = base.inverse()
    return [inverse * c.tool for c in found]


def arm_working_yaw(desc: RobotDescription, arm: str) -> float:
    """The direction [rad] about the base's z that ``arm`` works in (0: straight ahead)."""
    loaded = _loaded(desc)
    spec = loaded.arms[arm]
    return working_yaw(loaded.model, spec) if spec.joints else 0.0


def shoulder_offset(desc: RobotDescription, arm: str) -> float:
    """Sideways offset [m] of the arm's first joint across its working direction (the
    base's y for an arm working ahead): the line it reaches along."""
    loaded = _loaded(desc)
    spec = loaded.arms[arm]
    if not spec.joints:
        return 0.0
    key = (spec.joints, spec.end_effector_link)  # the model's FK and working yaw of them
    found = loaded.model.derived(_ShoulderOffsets).found  # costmaps ask per arm per stand
    if key not in found:
        x, y, _ = forward_kinematics(loaded, {}, loaded.model.joints[spec.joints[0]].child).position
        turn = arm_working_yaw(loaded, arm)
        found[key] = -math.sin(turn) * x + math.cos(turn) * y
    return found[key]


class _ShoulderOffsets:
    """Shoulder offsets found for one model, by arm chain."""

    def __init__(self, model: object) -> None:
        self.found: dict[tuple[object, ...], float] = {}


def _loaded(desc: RobotDescription) -> LoadedDescription:
    """``desc`` checked and with its model: as it is when already loaded (loading again
    re-runs every check, ~3 ms, and costmaps ask per arm per stand)."""
    return desc if isinstance(desc, LoadedDescription) else load_description(desc)

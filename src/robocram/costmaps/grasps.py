"""The grasps the reachability costmap checks: the grasp model's, seen from a base pose.

The costmap and the plans use one grasp model (``robocram.grasping``, docs/grasping.md):
the validator tries the same grasps, best first, that ``pick_up_object`` will, so a pose
it accepts is one the plan can grasp from.
"""

from __future__ import annotations

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
from robocram.robots import RobotDescription, load_description
from robocram.tf import Pose
from robocram.world import World, WorldObject

ANY_HAND = Hand(max_opening=float("inf"))  # where a grasp from above closes, whatever the hand


def approach_axis(desc: RobotDescription, arm: str) -> NDArray[np.float64]:
    """The unit approach axis of ``arm``'s tool, in the tool frame."""
    return np.asarray(tool_approach_axis(desc, arm), dtype=float)


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


def shoulder_offset(desc: RobotDescription, arm: str) -> float:
    """Sideways offset [m] (base y) of the arm's first joint: the line it reaches along."""
    model = load_description(desc).model
    first = model.joints[desc.arms[arm].joints[0]] if desc.arms[arm].joints else None
    if first is None:
        return 0.0
    return forward_kinematics(desc, {}, first.child).position[1]

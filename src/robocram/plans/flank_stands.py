"""Stands with the base's flank to the object: a base longer than it is wide stands nearer.

The reach costmap turns the base so its arm's working direction faces the object. The
Ridgeback's front reaches 0.47 m ahead of its middle, where the UR5 turns on its pan, and
its flanks 0.40 m: facing the kitchen counter, its base stands 0.74 m from the mug or more,
and its arm's forearm meets the counter's top taking the mug's side (49 mm deep at best of
75 IK solutions); turned a quarter, its middle stands 0.67 m from the mug, the forearm
clears the top by 13 mm, and it lifts the mug by its side. After every usual stand failed,
the fetch of a suction hand (no gripper joints; fingered hands have their own side grasps)
tries these: the base's middle :data:`FLANK_DISTANCES` from the object on the
robot's side of it, turned a quarter either way (a stand whose base meets the counter is
refused to the drive, which costs no try). The side is the robot's bearing from the
object snapped to the axes of the environment whose surfaces things stand on
(``supporting_surface/2``: a kitchen's counters run along its frame's axes): 1 cm from
the counter's drawers, a base turned 10 degrees off square meets them.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from robocram.knowledge.scene_predicates import SUPPORTING_SURFACE
from robocram.knowledge.world_predicates import OBJECT_POSE
from robocram.logic import UnknownPredicateError, current_kb
from robocram.plans.known_robot import KnownRobot
from robocram.plans.stands import map_pose, planar_pose, yaw_of
from robocram.tf import Pose, PoseStamped

FLANK_DISTANCES = (0.67, 0.70)  # [m] base's middle to the object: a flank 0.40 m out
# standing clear of a counter whose front (its drawers' handles) lies 0.26 m before it
QUARTERS = (math.pi / 2, -math.pi / 2)  # [rad] the base turned from facing the object


def squared(bearing: float) -> float:
    """``bearing`` [rad, map] snapped to the nearest axis of the environment with
    supporting surfaces; as it is when the KB names none (or not its pose)."""
    kb = current_kb()
    try:
        surface = SUPPORTING_SURFACE.first(kb)
    except UnknownPredicateError:  # no environment's semantics (a bare table)
        return bearing
    row = None if surface is None else OBJECT_POSE.first(kb, object=surface.environment)
    if row is None:
        return bearing
    axis = yaw_of(row.pose)
    return axis + round((bearing - axis) / (math.pi / 2)) * (math.pi / 2)


def flank_stands(
    robot: KnownRobot, where: PoseStamped, arm: str | None
) -> Iterator[tuple[Pose, str | None]]:
    """Stands (map) :data:`FLANK_DISTANCES` from the object (seen at ``where``, map) on
    the side the robot stands now (:func:`squared`), the base turned a quarter from facing
    it; the arm to use."""
    here = map_pose(robot.base_frame()).position
    x, y, _ = where.pose.position
    out = squared(math.atan2(here[1] - y, here[0] - x))  # object to robot
    for distance in FLANK_DISTANCES:
        for quarter in QUARTERS:
            sx, sy = x + math.cos(out) * distance, y + math.sin(out) * distance
            yield planar_pose(sx, sy, out + math.pi + quarter), arm

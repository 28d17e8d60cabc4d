"""Where to stand to place a held object or to pull a handle, from the robot's own geometry.

Placing: the arm already holds the object at a pose it reached, so a base pose that puts
the object over the placing spot *at the same place relative to the base* is reachable
by construction (the arm only lowers it). The stands turn about the spot, the first one
on the side the robot comes from, so the robot tries the near side of a table first.

Handles: the robot faces the handle from in front of its unit (the environment's
``container_front/3``, else the handle's x axis), far enough back for a drawer to open,
with the chosen arm's shoulder in line with the handle; an arm that works sideways
(Stretch's, ``arm_working_direction/3``) has the base turned so it points at it.
Everything comes from the KB and the transform tree: no link names.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from robocram.plans.known_robot import KnownRobot
from robocram.tf import Pose, PoseStamped, transform_pose
from robocram.tf import quaternion as quat

STAND_TURNS = 12  # placing stands per spot: turns about it, 30 degrees apart
HANDLE_CLEARANCES = (0.5, 0.6, 0.4)  # [m] base centre to an opened drawer's handle
REACH_DISTANCES = (0.55, 0.65, 0.45, 0.75, 0.85)  # [m] base to an object in an open container
DOOR_DISTANCES = (0.8, 0.9, 0.7)  # [m] base centre to a closed door's handle


def map_pose(frame: str) -> Pose:
    """The pose of ``frame`` in map, now."""
    return transform_pose(PoseStamped(frame), "map").pose


def yaw_of(pose: Pose) -> float:
    """The heading [rad] of ``pose`` about the vertical."""
    return quat.to_euler(pose.orientation)[2]


def planar_pose(x: float, y: float, yaw: float) -> Pose:
    """A base pose on the floor at ``(x, y)`` [m] heading ``yaw`` [rad]."""
    return Pose((x, y, 0.0), quat.from_euler(0.0, 0.0, yaw))


def _turns() -> list[float]:
    """0, +30, -30, +60, ... degrees: the first stand is tried first, then its neighbours."""
    step = 2 * math.pi / STAND_TURNS
    turns = [0.0]
    for k in range(1, STAND_TURNS // 2 + 1):
        turns.extend([k * step, -k * step] if k < STAND_TURNS // 2 else [k * step])
    return turns


def placing_stands(robot: KnownRobot, held_object: str, spot: Pose) -> Iterator[Pose]:
    """Base poses (map) that hold ``held_object`` over ``spot`` as the arm holds it now."""
    base = robot.base_frame()
    held_in_base = transform_pose(PoseStamped(held_object), base).pose.position
    here = map_pose(base).position
    sx, sy = spot.position[0], spot.position[1]
    bearing = math.atan2(held_in_base[1], held_in_base[0])  # of the object, seen from the base
    towards_robot = math.atan2(here[1] - sy, here[0] - sx)
    first = towards_robot + math.pi - bearing  # base heading with the base on the robot's side
    for turn in _turns():
        yaw = first + turn
        c, s = math.cos(yaw), math.sin(yaw)
        x = sx - (c * held_in_base[0] - s * held_in_base[1])
        y = sy - (s * held_in_base[0] + c * held_in_base[1])
        yield planar_pose(x, y, yaw)


@dataclass(frozen=True)
class HandleStand:
    """A base pose (map) in front of a handle and the arm that pulls it from there."""

    pose: Pose
    arm: str


def shoulder_offset(robot: KnownRobot, arm: str) -> float:
    """Sideways offset [m] of ``arm``'s first link from the base (its reaching line),
    across the arm's working direction (the base's y for an arm working ahead)."""
    shoulder = robot.first_arm_link(arm)
    if shoulder is None:
        return 0.0
    x, y, _ = transform_pose(PoseStamped(shoulder), robot.base_frame()).pose.position
    turn = robot.working_yaw(arm)
    return -math.sin(turn) * x + math.cos(turn) * y


def handle_stands(
    robot: KnownRobot,
    arms: list[str],
    handle_pose: Pose,
    opening: float,
    drawer: bool,
    front: float | None = None,
) -> Iterator[HandleStand]:
    """Stands facing the handle at ``handle_pose`` (map) from its unit's ``front``.

    ``front`` [rad] is the map yaw out of the unit's front; when the environment does not
    say, the handle's x axis is taken to point out of it.
    """
    distances = [opening + c for c in HANDLE_CLEARANCES] if drawer else list(DOOR_DISTANCES)
    out_yaw = front if front is not None else yaw_of(handle_pose)
    return front_stands(robot, arms, handle_pose, out_yaw, distances)


def front_stands(
    robot: KnownRobot, arms: list[str], point: Pose, out_yaw: float, distances: Iterable[float]
) -> Iterator[HandleStand]:
    """Stands facing ``point`` from the direction ``out_yaw`` [rad] (a unit's front), each
    arm's shoulder in line with it, ``distances`` [m] away, per arm in order."""
    facing = out_yaw + math.pi  # the arm's working direction faces the unit
    out = (math.cos(out_yaw), math.sin(out_yaw))
    left = (-math.sin(facing), math.cos(facing))  # across the working direction, in map
    hx, hy = point.position[0], point.position[1]
    distances = list(distances)
    for arm in arms:
        side = shoulder_offset(robot, arm)
        yaw = facing - robot.working_yaw(arm)
        for distance in distances:
            x = hx + out[0] * distance - left[0] * side
            y = hy + out[1] * distance - left[1] * side
            yield HandleStand(planar_pose(x, y, yaw), arm)

"""A flying robot in projection: straight flights checked for collisions, and a range sensor.

``fly`` moves the body along the straight segment to the target in steps of at most
``PATH_STEP``; every step must be free (contacts the robot already had where it started
do not count for the first ``TAKE_OFF`` metres, so it can lift off the floor). A collision
on the way or at the goal leaves it where it was and raises ``FlyingGoalInCollision``.
``sense_distance`` casts a ray from the body origin along a direction in the body frame.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from robocram.execution.failures import FlyingGoalInCollision
from robocram.projection.errors import ProjectionError
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose, PoseLike, PoseStamped
from robocram.tf import quaternion as quat

PATH_STEP = 0.05  # [m] between collision checks along a flight
TAKE_OFF = 0.1  # [m] along the path in which start contacts are tolerated
MAX_RANGE = 20.0  # [m] of the distance sensor


def _interpolate(start: Pose, goal: Pose, t: float) -> Pose:
    p = (1 - t) * np.asarray(start.position) + t * np.asarray(goal.position)
    q0, q1 = np.asarray(start.orientation), np.asarray(goal.orientation)
    if float(q0 @ q1) < 0:
        q1 = -q1
    q = (1 - t) * q0 + t * q1
    q /= np.linalg.norm(q)
    return Pose((p[0], p[1], p[2]), (q[0], q[1], q[2], q[3]))


def fly(robot: ProjectedRobot, target: PoseStamped | PoseLike) -> Pose:
    """Fly the robot's body in a straight line to ``target``; return the reached pose.

    Raises:
        FlyingGoalInCollision: the path or the goal hits something; the robot stays put.
    """
    world = robot.world
    start = robot.base_pose()
    goal = robot.in_map(target)
    length = start.distance_to(goal)
    steps = max(1, math.ceil(length / PATH_STEP))
    at_start = {o.name for o in world.collisions(robot.name)}
    for k in range(1, steps + 1):
        pose = _interpolate(start, goal, k / steps)
        world.set_pose(robot.name, pose)
        hit = {o.name for o in world.collisions(robot.name)}
        if k * length / steps <= TAKE_OFF and k < steps:
            hit -= at_start
        if hit:
            world.set_pose(robot.name, start)
            raise FlyingGoalInCollision(
                f"{robot.name} flying to {goal.position} hits {sorted(hit)} at {pose.position}",
                target=target,
                colliding=sorted(hit),
            )
    return goal


def sense_distance(robot: ProjectedRobot, direction: Sequence[float]) -> float:
    """Range [m] from the body origin to the first other thing along ``direction`` (body frame).

    Returns ``inf`` when nothing is within ``MAX_RANGE``.
    """
    d = np.asarray(direction, float)
    if d.shape != (3,) or not np.all(np.isfinite(d)) or np.linalg.norm(d) < 1e-9:
        raise ProjectionError(f"distance sensing needs a non-zero 3-D direction, got {direction!r}")
    base = robot.base_pose()
    d_map = np.asarray(quat.rotate(base.orientation, tuple(d / np.linalg.norm(d))))
    origin = np.asarray(base.position)
    start = origin
    for _ in range(16):  # rays starting inside the robot's own shapes re-start past them
        hit = robot.world.ray_cast(tuple(start), tuple(origin + MAX_RANGE * d_map))
        if hit is None:
            return math.inf
        if hit.obj.name != robot.name:
            return float(np.linalg.norm(np.asarray(hit.position) - origin))
        start = np.asarray(hit.position) + 1e-3 * d_map
    return math.inf

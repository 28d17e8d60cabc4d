"""A flying robot in projection: straight flights checked for collisions, and a range sensor.

``fly`` checks the straight segment to the target (position and each of roll, pitch and
yaw the short way) with no point of the body moving more than ``PATH_STEP`` between two
checks; every step must be free (contacts the robot already had where it started do not
count for the first ``TAKE_OFF`` metres, so it can lift off the floor). A collision on the
way or at the goal leaves it where it was and raises ``FlyingGoalInCollision``. A free
flight is a timed trajectory of the body's joints (``BODY_JOINTS``), followed and traced
like every other motion: the body no longer jumps to its goal.
``sense_distance`` casts a ray from the body origin along a direction in the body frame.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from robocram.execution.failures import FlyingGoalInCollision
from robocram.motion import BODY_JOINTS, joint_limits, time_parameterize
from robocram.projection.errors import ProjectionError
from robocram.projection.path_watch import planned_against
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.trajectory_follower import follow
from robocram.tf import Pose, PoseLike, PoseStamped
from robocram.tf import quaternion as quat

PATH_STEP = 0.01  # [m] the most a point of the body moves between two collision checks
TAKE_OFF = 0.1  # [m] along the path in which start contacts are tolerated
MAX_RANGE = 20.0  # [m] of the distance sensor


def _values(pose: Pose) -> np.ndarray:
    """The body's joints (:data:`BODY_JOINTS`: x, y, z, roll, pitch, yaw) of ``pose``."""
    return np.array([*pose.position, *quat.to_euler(pose.orientation)])


def _pose(values: np.ndarray) -> Pose:
    x, y, z, roll, pitch, yaw = (float(v) for v in values)
    return Pose((x, y, z), quat.from_euler(roll, pitch, yaw))


def fly(robot: ProjectedRobot, target: PoseStamped | PoseLike) -> Pose:
    """Fly the robot's body in a straight line to ``target`` (each angle the short way
    round); return the reached pose. The flight is checked for collisions with no point
    of the body moving more than :data:`PATH_STEP` between two checks, then timed under the
    body's velocity, acceleration and jerk limits and followed, so traces store it.

    Raises:
        FlyingGoalInCollision: the path or the goal hits something; the robot stays put.
    """
    world = robot.world
    start = robot.base_pose()
    goal = robot.in_map(target)
    a, b = _values(start), _values(goal)
    b[3:] = a[3:] + np.array([math.remainder(float(d), math.tau) for d in b[3:] - a[3:]])
    checked = planned_against(robot)  # what the flight is checked against
    radius = max(world.contacts.link_radii(robot.name).values(), default=0.0)
    travel = float(np.linalg.norm(b[:3] - a[:3])) + radius * float(np.abs(b[3:] - a[3:]).sum())
    length = float(np.linalg.norm(b[:3] - a[:3]))
    steps = max(1, math.ceil(travel / PATH_STEP))
    at_start = {o.name for o in world.contacts.collisions(robot.name)}
    try:
        for k in range(1, steps + 1):
            values = a + (b - a) * (k / steps)
            world.set_pose(robot.name, _pose(values))
            hit = {o.name for o in world.contacts.collisions(robot.name)}
            if k * length / steps <= TAKE_OFF and k < steps:
                hit -= at_start
            if hit:
                raise FlyingGoalInCollision(
                    f"{robot.name} flying to {goal.position} hits {sorted(hit)} at "
                    f"{tuple(round(float(v), 3) for v in values[:3])}",
                    target=target,
                    colliding=sorted(hit),
                )
    finally:
        world.set_pose(robot.name, start)  # the trajectory moves it
    limits = joint_limits(robot.description, BODY_JOINTS)
    path = np.array([a, b])
    flight = time_parameterize(robot.name, BODY_JOINTS, path, limits, kind="flight")
    follow(robot, flight, checked)
    return robot.base_pose()


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
        hit = robot.world.view.ray_cast(tuple(start), tuple(origin + MAX_RANGE * d_map))
        if hit is None:
            return math.inf
        if hit.obj.name != robot.name:
            return float(np.linalg.norm(np.asarray(hit.position) - origin))
        start = np.asarray(hit.position) + 1e-3 * d_map
    return math.inf

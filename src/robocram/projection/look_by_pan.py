"""Looking with a head that only pans (Baxter's): turn it, and accept the tilt it has.

The pan joint is aimed as a pan-tilt head's is (``joint_aim.py``) and turned along a
checked, timed trajectory. The camera's tilt is fixed, so the look succeeds when the
target then lies inside the camera's field of view (read from the camera link's pose in
the world after the turn); otherwise ``PtuGoalNotReached`` says how far outside, and on
which side, the target lies.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.execution.failures import ManipulationPathBlocked, PtuGoalNotReached
from robocram.projection.joint_aim import aimed_joints
from robocram.projection.joint_motion import move_along_checked
from robocram.projection.look_failures import look_blocked
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose, Vector3


def view_angles(robot: ProjectedRobot, target_in_map: Vector3) -> tuple[float, float, float]:
    """[rad, rad, m] the target's angle along the first camera's x and y axes off its
    optical axis, and its depth along it, from the camera frame's pose in the world now."""
    frame = robot.description.cameras[0].frame
    camera = robot.world.link_pose(robot.name, frame)
    x, y, z = (camera.inverse() * Pose(target_in_map)).position
    return math.atan2(x, z), math.atan2(y, z), z


def _elevation(vector: np.ndarray) -> float:
    return math.atan2(float(vector[2]), float(np.linalg.norm(vector[:2])))


def _outside(robot: ProjectedRobot, target_in_map: Vector3) -> str | None:
    """Where the target lies outside the camera's view, in words; None inside it. Above
    or below is read against the world's up (a camera frame's y need not point down)."""
    camera = robot.description.cameras[0]
    across, along, depth = view_angles(robot, target_in_map)
    if depth <= 0.0:
        return "behind the camera"
    misses = [abs(a) - half for a, half in ((across, camera.horizontal_fov / 2),
                                             (along, camera.vertical_fov / 2))]  # fmt: skip
    if max(misses) <= 0.0:
        return None
    pose = robot.world.link_pose(robot.name, camera.frame)
    axis = pose.matrix()[:3, 2]
    to_target = np.subtract(target_in_map, pose.position)
    word = "below" if _elevation(to_target) < _elevation(axis) else "above"
    return f"{math.degrees(max(misses)):.0f} degrees outside the camera's view ({word} it)"


def look_by_pan(
    robot: ProjectedRobot, joint: str, link: str, target_in_map: Vector3
) -> dict[str, float]:
    """Pan ``joint`` so the camera faces ``target_in_map``; the joint's value reached.

    Raises:
        PtuPathBlocked: the turn runs into something; the head did not move.
        PtuGoalNotReached: after the turn the target lies outside the camera's view (the
            head cannot tilt), or the pan needed is outside the joint's limits.
    """
    world = robot.world
    wanted = aimed_joints(robot, ((joint, link),), np.asarray(target_in_map, float))
    inside = {joint: world.bodies.joint_limits(robot.name, joint).clamp(wanted[joint])}
    try:
        reached = move_along_checked(
            robot, inside, kind="head", what=f"{robot.name}'s head", plan=True
        )
    except ManipulationPathBlocked as blocked:
        raise look_blocked(robot, target_in_map, blocked, "head") from blocked
    missed = _outside(robot, target_in_map)
    if missed is not None:
        clamped = " (the pan clamped to its limits)" if inside != wanted else ""
        at = ", ".join(f"{v:.2f}" for v in target_in_map)
        raise PtuGoalNotReached(
            f"{robot.name}'s head only pans ({joint}){clamped}: the target ({at}) lies "
            f"{missed}; look at it from farther away or turn the base towards it",
            target=tuple(target_in_map),
            reached=reached,
        )
    return reached

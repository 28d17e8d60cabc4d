"""Looking in projection: turn the head so the camera's optical axis points at a target.

Pan-tilt heads (PR2, HSR) are aimed joint by joint: each joint turns by the angle between
the optical axis and the direction to the target, both projected onto the plane normal to
the joint axis; a few rounds absorb the camera's offset from the axes. The rounds place
the links on the robot's kinematic model (from its base pose in the world). The head
then turns to the aimed values along a checked, timed trajectory (``joint_motion.py``,
kind ``head``); a turn that runs into something fails with ``PtuPathBlocked`` before the
head moves. Angles outside the limits are clamped and turned to, then
``PtuGoalNotReached`` is raised (CRAM's semantics). A neck that is an arm (Boxy) is aimed
by IK: the camera turns to face the target from its current place, else from the neck's
parking place or a step away from the current one; ``PtuGoalUnreachable`` if IK finds no
solution for any of them. A robot with neither looks with what turns its camera
(``looking_means.py``): the arm carrying it (``look_by_arm.py``) or a head that only pans
(``look_by_pan.py``); one whose camera nothing turns only checks the target is in view
(``look_fixed.py``).
"""

from __future__ import annotations

import math

import numpy as np

from robocram.execution.failures import (
    ManipulationPathBlocked,
    PtuGoalNotReached,
    PtuGoalUnreachable,
)
from robocram.kinematics import IKOptions, forward_kinematics, solve_ik
from robocram.projection.errors import ProjectionError
from robocram.projection.joint_aim import aimed_joints
from robocram.projection.joint_motion import move_along_checked
from robocram.projection.look_by_arm import look_by_arm
from robocram.projection.look_by_pan import look_by_pan
from robocram.projection.look_failures import look_blocked
from robocram.projection.look_fixed import look_fixed
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import PanTiltDescription
from robocram.robots.looking_means import looking_means
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
from robocram.tf.optical_look_at import optical_look_at

NECK_STEP = 0.15  # [m] how far from its current place a neck arm may move the camera


def look_at(robot: ProjectedRobot, target_in_map: Vector3) -> dict[str, float]:
    """Point the robot's first camera at ``target_in_map`` [m]; return the joints set."""
    desc = robot.description
    if not desc.cameras:
        raise ProjectionError(f"{robot.name} has no camera to look with")
    means = looking_means(desc)
    if means is None:  # nothing turns the camera: the target must be in its view
        return look_fixed(robot, target_in_map)
    if means.kind == "pan_tilt" and desc.pan_tilt is not None:
        return _aim_pan_tilt(robot, desc.pan_tilt, target_in_map)
    if means.kind == "neck_arm" and desc.neck_arm is not None:
        return _aim_neck_arm(robot, desc.neck_arm, target_in_map)
    if means.kind == "arm" and means.arm is not None:
        return look_by_arm(robot, means.arm, target_in_map)
    if means.joint is None or means.link is None:
        raise ProjectionError(f"{robot.name}'s looking means {means} names no joint to turn")
    return look_by_pan(robot, means.joint, means.link, target_in_map)


def _aim_pan_tilt(
    robot: ProjectedRobot, pt: PanTiltDescription, target_in_map: Vector3
) -> dict[str, float]:
    world, target = robot.world, np.asarray(target_in_map, float)
    wanted = aimed_joints(robot, pt.axes(), target)
    bounds = {j: world.bodies.joint_limits(robot.name, j) for j in wanted}
    inside = {j: bounds[j].clamp(v) for j, v in wanted.items()}
    reached = _turn_head(robot, inside, target_in_map)
    if inside != wanted:
        limits = {j: (b.lower, b.upper) for j, b in bounds.items() if inside[j] != wanted[j]}
        below = pt.tilt_joint in limits and _below_axis(robot, target_in_map)
        share = view_share(robot, target_in_map) if below else None
        lower = (
            f"; the target lies below what it tilts down to, {share[1]:.2f} of the half "
            "field under the axis: lower the camera"
            if share is not None
            else ""
        )
        raise PtuGoalNotReached(
            f"looking at {tuple(target_in_map)} needs {wanted}, outside the limits {limits} "
            f"of {robot.name}'s head; turned to {reached} instead{lower}",
            target=tuple(target_in_map),
            reached=reached,
            below_tilt=below,
            view_share=share,
        )
    return reached


def _below_axis(robot: ProjectedRobot, target_in_map: Vector3) -> bool:
    """Whether ``target_in_map`` lies below the camera's optical axis as the head is turned:
    a tilt stopped at its limit short of it, a lower camera (the torso down) sees it."""
    view = robot.world.link_pose(robot.name, robot.description.cameras[0].frame)
    axis = (Pose(orientation=view.orientation) * Pose((0.0, 0.0, 1.0))).position
    to = np.subtract(target_in_map, view.position)
    return bool(to[2] / np.linalg.norm(to) < axis[2] - 1e-6)


def view_share(robot: ProjectedRobot, target_in_map: Vector3) -> tuple[float, float]:
    """Where ``target_in_map`` lies in the first camera's view as the head is turned: its
    angles off the optical axis (aside: + right, below: + down) as shares of the half
    fields of the robot's description (1 at the view's edge): a head stopped at its tilt
    limit may still see a target a little under its axis (TALOS's, 45 degrees down)."""
    camera = robot.description.cameras[0]
    view = robot.world.link_pose(robot.name, camera.frame)
    tx, ty, tz = target_in_map
    x, y, z = (view.inverse() * Pose((tx, ty, tz))).position
    aside = math.atan2(x, z) / (camera.horizontal_fov / 2)
    below = math.atan2(y, z) / (camera.vertical_fov / 2)
    return aside, below


def _turn_head(
    robot: ProjectedRobot, goal: dict[str, float], target_in_map: Vector3
) -> dict[str, float]:
    """Turn the head's joints to ``goal`` along a checked, timed trajectory.

    Raises:
        PtuPathBlocked: the turn runs into something; the head did not move.
    """
    try:
        return move_along_checked(robot, goal, kind="head", what=f"{robot.name}'s head", plan=True)
    except ManipulationPathBlocked as blocked:
        raise look_blocked(robot, target_in_map, blocked, "head") from blocked


def looking_orientation(camera_position: Vector3, target: Vector3) -> quat.Quaternion:
    """Optical-frame orientation (z forward, x right, y down) facing ``target`` from the camera."""
    if np.linalg.norm(np.subtract(target, camera_position)) < 1e-6:
        raise ProjectionError(f"look target {target} is at the camera; look somewhere else")
    return optical_look_at(camera_position, target)


def _camera_positions(robot: ProjectedRobot, frame: str) -> list[Vector3]:
    """Where the neck may hold the camera: now, at the neck's parking pose, and nearby."""
    desc, world = robot.description, robot.world
    now = world.link_pose(robot.name, frame).position
    places = [now]
    if desc.neck_parking:
        parked = forward_kinematics(desc, dict(desc.neck_parking), frame)
        places.append((robot.base_pose() * parked).position)
    for axis in range(3):
        for sign in (1.0, -1.0):
            moved = list(now)
            moved[axis] += sign * NECK_STEP
            places.append((moved[0], moved[1], moved[2]))
    return places


def _aim_neck_arm(robot: ProjectedRobot, neck: str, target_in_map: Vector3) -> dict[str, float]:
    """Aim the neck by IK from where it is; where every goal so found is blocked, turn it
    to its parking configuration (a checked motion) and aim it from there: a Boxy's neck,
    wound up by the looks before (pan 2.23, lift -2.27 rad; parked 1.43, 0.39), found for
    every look into a drawer only goals with its forearm against the torso. A neck that
    could not be aimed from its parking configuration either stays parked.

    Raises:
        PtuPathBlocked: every goal was blocked (from the parking configuration too).
        PtuGoalUnreachable: IK found no goal.
    """
    desc = robot.description
    errors: list[float] = []
    blocked: list[ManipulationPathBlocked] = []
    reached = _aim_neck_from(robot, neck, target_in_map, errors, blocked)
    if reached is None and blocked and _parked_neck(robot):
        reached = _aim_neck_from(robot, neck, target_in_map, errors, [])
    if reached is not None:
        return reached
    frame = desc.cameras[0].frame
    if blocked:
        raise look_blocked(robot, target_in_map, blocked[0], "head") from blocked[0]
    raise PtuGoalUnreachable(
        f"{robot.name}'s neck cannot point {frame} at {tuple(target_in_map)} from any of "
        f"{len(errors)} camera positions tried (best IK miss {min(errors):.3f} m)",
        target=tuple(target_in_map),
    )


def _parked_neck(robot: ProjectedRobot) -> bool:
    """Turn the neck to its parking configuration along a checked, timed trajectory;
    whether it got there (False: it has none, or the way is blocked; it did not move)."""
    parking = dict(robot.description.neck_parking or {})
    if not parking:
        return False
    try:
        move_along_checked(robot, parking, kind="head", what=f"{robot.name}'s neck", plan=True)
    except ManipulationPathBlocked:
        return False
    return True


def _aim_neck_from(
    robot: ProjectedRobot,
    neck: str,
    target_in_map: Vector3,
    errors: list[float],
    blocked: list[ManipulationPathBlocked],
) -> dict[str, float] | None:
    """The joints set by the first camera place whose IK (seeded where the neck is) the
    neck turns to; None if none (each IK miss added to ``errors``, each blocked turn to
    ``blocked``)."""
    desc, world = robot.description, robot.world
    frame = desc.cameras[0].frame
    seed = world.joint_states(robot.name)
    for place in _camera_positions(robot, frame):
        view = Pose(place, looking_orientation(place, target_in_map))
        target_in_base = robot.base_pose().inverse() * view
        with robot.ik_lock:
            result = solve_ik(desc, neck, target_in_base, seed=seed, options=IKOptions(frame=frame))
        if not result.success:
            errors.append(result.position_error)
            continue
        try:
            return move_along_checked(
                robot, dict(result.joint_positions), kind="head",
                what=f"{robot.name}'s neck", plan=True,
            )  # fmt: skip
        except ManipulationPathBlocked as failure:  # another camera place may be free
            blocked.append(failure)
    return None

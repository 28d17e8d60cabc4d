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
solution for any of them.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.execution.failures import (
    ManipulationPathBlocked,
    PtuGoalNotReached,
    PtuGoalUnreachable,
    PtuPathBlocked,
)
from robocram.kinematics import IKOptions, forward_kinematics, solve_ik
from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.projection.errors import ProjectionError
from robocram.projection.joint_motion import move_along_checked
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import PanTiltDescription
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
from robocram.tf.optical_look_at import optical_look_at
from robocram.tf.signed_angle import signed_angle
from robocram.world import JointLimits

AIM_ROUNDS = 6
AIM_TOLERANCE = 1e-4  # [rad] a round changing the joints less than this ends the aiming
NECK_STEP = 0.15  # [m] how far from its current place a neck arm may move the camera


def look_at(robot: ProjectedRobot, target_in_map: Vector3) -> dict[str, float]:
    """Point the robot's first camera at ``target_in_map`` [m]; return the neck joints set."""
    desc = robot.description
    if not desc.cameras:
        raise ProjectionError(f"{robot.name} has no camera to look with")
    if desc.pan_tilt is not None:
        return _aim_pan_tilt(robot, desc.pan_tilt, target_in_map)
    if desc.neck_arm is not None:
        return _aim_neck_arm(robot, desc.neck_arm, target_in_map)
    raise ProjectionError(
        f"{robot.name} has neither a pan-tilt unit nor a neck arm; it cannot look around"
    )


def _nearest_in_limits(value: float, limits: JointLimits) -> float:
    """``value`` or a 2*pi turn of it that lies within ``limits``, else ``value``."""
    for candidate in (value, value - 2 * math.pi, value + 2 * math.pi):
        if limits.lower <= candidate <= limits.upper:
            return candidate
    return value


def _aim_pan_tilt(
    robot: ProjectedRobot, pt: PanTiltDescription, target_in_map: Vector3
) -> dict[str, float]:
    world, target = robot.world, np.asarray(target_in_map, float)
    wanted = _aimed(robot, pt, target)
    bounds = {j: world.bodies.joint_limits(robot.name, j) for j in wanted}
    inside = {j: bounds[j].clamp(v) for j, v in wanted.items()}
    reached = _turn_head(robot, inside, target_in_map)
    if inside != wanted:
        limits = {j: (b.lower, b.upper) for j, b in bounds.items() if inside[j] != wanted[j]}
        raise PtuGoalNotReached(
            f"looking at {tuple(target_in_map)} needs {wanted}, outside the limits {limits} "
            f"of {robot.name}'s head; turned to {reached} instead",
            target=tuple(target_in_map),
            reached=reached,
        )
    return reached


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
        raise _blocked(robot, target_in_map, blocked) from blocked


def _blocked(
    robot: ProjectedRobot, target_in_map: Vector3, blocked: ManipulationPathBlocked
) -> PtuPathBlocked:
    return PtuPathBlocked(
        f"{robot.name} cannot turn its head to look at {tuple(target_in_map)}: {blocked}; "
        "the head did not move",
        target=tuple(target_in_map),
        colliding_pairs=blocked.colliding_pairs,
        path_fraction=blocked.path_fraction,
    )


def _aimed(robot: ProjectedRobot, pt: PanTiltDescription, target: np.ndarray) -> dict[str, float]:
    """The pan and tilt values that point the camera at ``target`` (map), unclamped.

    The rounds turn each joint in turn with the other held where the last turn (clamped
    to its limits, as setting it would) left it. The links are placed by the robot's
    kinematic model from its base pose in the world: a round costs microseconds, where
    setting the joints in the world and reading its links back cost a millisecond a look.
    """
    world, desc = robot.world, robot.description
    kin = robot_kinematics(desc.model)
    axes = pt.axes()
    frames = [kin.frame_id(link) for _, link in axes] + [kin.frame_id(desc.cameras[0].frame)]
    local_axes = [np.asarray(desc.model.joints[joint].axis, float) for joint, _ in axes]
    limits = [world.bodies.joint_limits(robot.name, joint) for joint, _ in axes]
    state = world.joint_states(robot.name)
    q = kin.configuration({j: v for j, v in state.items() if desc.model.joints[j].mimic is None})
    root = world.pose(robot.name).matrix()
    values = [state[joint] for joint, _ in axes]
    wanted: dict[str, float] = {}
    for _ in range(AIM_ROUNDS):
        before = list(values)
        for k, (joint, _) in enumerate(axes):
            placed = kin.frame_matrices(q, (frames[k], frames[-1]))
            link, view = root @ placed[0], root @ placed[1]
            axis = link[:3, :3] @ local_axes[k]
            axis /= np.linalg.norm(axis)
            turn = signed_angle(view[:3, 2], target - view[:3, 3], axis)
            wanted[joint] = _nearest_in_limits(values[k] + turn, limits[k])
            values[k] = limits[k].clamp(wanted[joint])
            kin.put(q, joint, values[k])
        if max(abs(a - b) for a, b in zip(values, before, strict=True)) < AIM_TOLERANCE:
            break
    return wanted


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
    desc, world = robot.description, robot.world
    frame = desc.cameras[0].frame
    seed = world.joint_states(robot.name)
    errors = []
    blocked: list[ManipulationPathBlocked] = []
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
    if blocked:
        raise _blocked(robot, target_in_map, blocked[0]) from blocked[0]
    raise PtuGoalUnreachable(
        f"{robot.name}'s neck cannot point {frame} at {tuple(target_in_map)} from any of "
        f"{len(errors)} camera positions tried (best IK miss {min(errors):.3f} m)",
        target=tuple(target_in_map),
    )

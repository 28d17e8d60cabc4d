"""Looking in projection: turn the head so the camera's optical axis points at a target.

Pan-tilt heads (PR2, HSR) are aimed joint by joint: each joint turns by the angle between
the optical axis and the direction to the target, both projected onto the plane normal to
the joint axis; a few rounds absorb the camera's offset from the axes. Angles outside the
limits are clamped and applied, then ``PtuGoalNotReached`` is raised (CRAM's semantics).
A neck that is an arm (Boxy) is aimed by IK: the camera turns to face the target from
its current place, else from the neck's parking place or a step away from the current
one; ``PtuGoalUnreachable`` if IK finds no solution for any of them.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.execution.failures import PtuGoalNotReached, PtuGoalUnreachable
from robocram.kinematics import forward_kinematics, solve_ik
from robocram.projection.errors import ProjectionError
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import PanTiltDescription
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
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


def _aim_joint(
    robot: ProjectedRobot, joint: str, child_link: str, target: np.ndarray, current: float
) -> float:
    """The value of ``joint`` (now ``current``) that turns the optical axis towards
    ``target``, unclamped."""
    world, desc = robot.world, robot.description
    spec = desc.model.joints[joint]
    link = world.link_pose(robot.name, child_link).matrix()
    axis = link[:3, :3] @ np.asarray(spec.axis, float)
    axis /= np.linalg.norm(axis)
    camera = world.link_pose(robot.name, desc.cameras[0].frame).matrix()
    optical = camera[:3, 2]
    wanted = target - camera[:3, 3]
    turn = signed_angle(optical, wanted, axis)
    return _nearest_in_limits(current + turn, world.joint_limits(robot.name, joint))


def _aim_pan_tilt(
    robot: ProjectedRobot, pt: PanTiltDescription, target_in_map: Vector3
) -> dict[str, float]:
    world, target = robot.world, np.asarray(target_in_map, float)
    wanted: dict[str, float] = {}
    after = world.joint_states(robot.name)
    for _ in range(AIM_ROUNDS):
        before = after  # setting one pan-tilt joint leaves the other's value: read once a round
        for joint, link in pt.axes():
            wanted[joint] = _aim_joint(robot, joint, link, target, before[joint])
            world.set_joint_states(robot.name, {joint: wanted[joint]})
        after = world.joint_states(robot.name)
        if max(abs(after[j] - before[j]) for j in wanted) < AIM_TOLERANCE:
            break
    clamped = world.set_joint_states(robot.name, wanted)
    reached = {j: world.joint_states(robot.name)[j] for j in wanted}
    if clamped:
        limits = {c.name: (c.lower, c.upper) for c in clamped}
        raise PtuGoalNotReached(
            f"looking at {tuple(target_in_map)} needs {wanted}, outside the limits {limits} "
            f"of {robot.name}'s head; turned to {reached} instead",
            target=tuple(target_in_map),
            reached=reached,
        )
    return reached


def looking_orientation(camera_position: Vector3, target: Vector3) -> quat.Quaternion:
    """Optical-frame orientation (z forward, x right, y down) facing ``target`` from the camera."""
    z = np.subtract(target, camera_position).astype(float)
    if np.linalg.norm(z) < 1e-6:
        raise ProjectionError(f"look target {target} is at the camera; look somewhere else")
    z /= np.linalg.norm(z)
    x = np.cross((0.0, 0.0, -1.0), z)
    if np.linalg.norm(x) < 1e-6:  # looking straight up or down: any right-hand axis works
        x = np.array((0.0, -1.0, 0.0))
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    m = np.eye(4)
    m[:3, :3] = np.column_stack((x, y, z))
    return Pose.from_matrix(m).orientation


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
    for place in _camera_positions(robot, frame):
        view = Pose(place, looking_orientation(place, target_in_map))
        target_in_base = robot.base_pose().inverse() * view
        with robot.ik_lock:
            result = solve_ik(desc, neck, target_in_base, seed=seed, frame=frame)
        if result.success:
            world.set_joint_states(robot.name, dict(result.joint_positions))
            return {j: world.joint_states(robot.name)[j] for j in result.joint_positions}
        errors.append(result.position_error)
    raise PtuGoalUnreachable(
        f"{robot.name}'s neck cannot point {frame} at {tuple(target_in_map)} from any of "
        f"{len(errors)} camera positions tried (best IK miss {min(errors):.3f} m)",
        target=tuple(target_in_map),
    )

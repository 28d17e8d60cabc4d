"""A robot's camera as it would be with the neck aimed at a point: same place, turned."""

from __future__ import annotations

import math

import numpy as np

from robocram.costmaps.errors import CostmapInputError
from robocram.tf import Pose, Vector3
from robocram.world import Camera, RobotObject, World

FAR_MARGIN = 1.0  # [m] the aimed camera sees this far behind its target
RAISE_MIN = 0.05  # [m] a wrist camera raised less than this is not tried apart


def facing(camera_position: Vector3, target: Vector3) -> Pose:
    """Optical-frame pose (z forward, x right, y down) at ``camera_position`` facing ``target``."""
    z = np.subtract(target, camera_position).astype(float)
    if np.linalg.norm(z) < 1e-6:
        raise CostmapInputError(f"camera and target coincide at {tuple(target)}", target)
    z /= np.linalg.norm(z)
    x = np.cross((0.0, 0.0, -1.0), z)
    if np.linalg.norm(x) < 1e-6:  # straight up or down: any right-hand x axis will do
        x = np.array((0.0, -1.0, 0.0))
    x /= np.linalg.norm(x)
    m = np.eye(4)
    m[:3, :3] = np.column_stack((x, np.cross(z, x), z))
    m[:3, 3] = camera_position
    return Pose.from_matrix(m)


def camera_description(world: World, robot: RobotObject, key: str = "visible_for") -> Camera:
    """The robot's first camera where it is now; a typed error if the robot has none."""
    cameras = robot.description.cameras
    if not cameras:
        raise CostmapInputError(
            f"location key {key!r} names robot {robot.name!r}, which has no camera in its "
            "description; use a robot with a camera or another key",
            robot.name,
        )
    return world.view.camera(robot)


def aimed_camera(world: World, robot: RobotObject, target: Vector3) -> Camera:
    """The robot's first camera turned in place to look at ``target`` (map, [m]).

    Its far plane sits just behind the target: rays that need not go further are cheaper.
    """
    camera = camera_description(world, robot)
    beyond = math.dist(camera.pose.position, target) + FAR_MARGIN
    return Camera(
        facing(camera.pose.position, target),
        camera.horizontal_fov,
        camera.vertical_fov,
        camera.near,
        max(camera.near * 2, min(camera.far, beyond)),
    )


def aimed_cameras(world: World, robot: RobotObject, target: Vector3) -> list[Camera]:
    """The cameras a stand's check may look with: the robot's first camera where it is,
    aimed at ``target``; for a camera an arm carries (no head, no neck: a wrist camera),
    also that camera raised to the description's maximal height, where the arm can hold it
    when it looks (``projection/look_by_arm.py``)."""
    now = aimed_camera(world, robot, target)
    desc = robot.description
    base_z = world.pose(robot).position[2]
    top = desc.cameras[0].maximal_height
    if desc.pan_tilt is not None or desc.neck_arm is not None or top is None:
        return [now]
    x, y, z = now.pose.position
    if base_z + top <= z + RAISE_MIN:
        return [now]
    high = (x, y, base_z + top)
    beyond = math.dist(high, target) + FAR_MARGIN
    raised = Camera(
        facing(high, target), now.horizontal_fov, now.vertical_fov, now.near,
        max(now.near * 2, min(camera_description(world, robot).far, beyond)),
    )  # fmt: skip
    return [now, raised]


def pitch_to(camera_position: Vector3, target: Vector3) -> float:
    """Angle [rad] below the horizontal at which the camera sees ``target``."""
    dx = math.hypot(target[0] - camera_position[0], target[1] - camera_position[1])
    return math.atan2(camera_position[2] - target[2], dx)

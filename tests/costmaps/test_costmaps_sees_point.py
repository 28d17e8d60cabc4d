"""The visibility validator's ray to a target point starts at the camera's near plane."""

from __future__ import annotations

import math

import pytest

from robocram.costmaps.camera_aim import aimed_camera
from robocram.costmaps.validators import parked, placed, sees_point
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

OVER_NORTH_COUNTER = (-1.4, 2.19, 0.93)  # [m] 10 cm over the counter, in map


def test_boxy_sees_over_the_counter_from_inside_its_camera_housing() -> None:
    scene = kitchen_scene("boxy")
    world = scene.world
    robot = world.robot(scene.robot)
    standing = Pose((-1.4, 0.8, 0.0), quat.from_euler(0.0, 0.0, math.pi / 2))
    with placed(world, robot, standing), parked(world, robot):
        camera = aimed_camera(world, robot, OVER_NORTH_COUNTER)
        from_origin = world.view.ray_cast(camera.pose.position, OVER_NORTH_COUNTER)
        assert from_origin is not None and from_origin.obj.name == "boxy"  # its own Kinect
        assert from_origin.distance < camera.near
        assert sees_point(world, camera, OVER_NORTH_COUNTER)
        below = (OVER_NORTH_COUNTER[0], OVER_NORTH_COUNTER[1], 0.5)  # inside the counter
        assert not sees_point(world, camera, below)
    world.close()


@pytest.mark.parametrize("robot", ["pr2", "hsrb"])
def test_other_cameras_see_the_same_point(robot: str) -> None:
    scene = kitchen_scene(robot)
    world = scene.world
    body = world.robot(scene.robot)
    standing = Pose((-1.4, 1.1, 0.0), quat.from_euler(0.0, 0.0, math.pi / 2))
    with placed(world, body, standing), parked(world, body):
        camera = aimed_camera(world, body, OVER_NORTH_COUNTER)
        assert sees_point(world, camera, OVER_NORTH_COUNTER)
    world.close()

"""A look into an opened drawer that stops at the head's tilt limit with the drawer's
middle still in the view has looked: perception judges what it sees.

TALOS's head tilts 45 degrees down at most. From where it stood once it had opened the
bowl's drawer (crouched, then up again), the middle of the drawer needs 1.12 rad: the head
stops at its limit with that middle 0.81 of the half field under its axis, in the view
but not within the half that counts as looked at, so the search sought the bowl at the
next place, saw it in the drawer from 1.7 m away and fetched it as if it lay on the counter
it had looked at. Judged on PyBullet's own state: the head's tilt joint as the look left
it, against its limit in the URDF, and the camera frame's pose.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from robocram.execution.failures import PtuGoalNotReached
from robocram.plans.basic_actions import detect, look_from_above
from robocram.plans.search import LOOK_ABOVE, look_into_opened
from robocram.projection import simulated_robot
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from tests.bullet_links import link_frame
from tests.talos_open_drawer import talos_kitchen_drawer_open

STAND = (-1.688, 1.109, math.radians(74.9))  # [m, m, rad] map: where it looked from


def test_a_look_into_an_opened_drawer_stopped_at_the_tilt_limit_sees_the_bowl() -> None:
    scene, before, after = talos_kitchen_drawer_open()
    world, robot = scene.world, scene.robot
    try:
        # the middle of what opening pulled out, a little over the link's frame
        middle = tuple(
            (a + b) / 2 + (LOOK_ABOVE if k == 2 else 0.0)
            for k, (a, b) in enumerate(zip(before.position, after.position, strict=True))
        )
        x, y, yaw = STAND
        height = world.pose(robot).position[2]
        world.set_pose(robot, Pose((x, y, height), quat.from_euler(0.0, 0.0, yaw)))
        point = PoseStamped("map", middle)
        with simulated_robot(world, robot):
            with pytest.raises(PtuGoalNotReached):
                look_from_above(point)  # the look alone fails: the tilt stops short
            look_into_opened(point)
            seen = detect("bowl")
        desc = world.robot(robot).description
        tilt = desc.pan_tilt
        assert tilt is not None
        limit = world.bodies.joint_limits(robot, tilt.tilt_joint).upper
        assert world.joint_states(robot)[tilt.tilt_joint] == pytest.approx(limit, abs=1e-3)
        camera = desc.cameras[0]
        position, rotation = link_frame(
            world.object(robot).body_id, world.physics.client(), camera.frame
        )
        cx, cy, cz = rotation.T @ (np.asarray(middle) - position)
        below = math.atan2(cy, cz) / (camera.vertical_fov / 2)
        assert 0.5 < below < 1.0  # in the view, not within the half that counts elsewhere
        assert below == pytest.approx(0.81, abs=0.03)
        assert abs(math.atan2(cx, cz)) < camera.horizontal_fov / 2
        assert seen.get("name") == "bowl-1"
    finally:
        world.close()

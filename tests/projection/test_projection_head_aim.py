"""Aiming a pan-tilt head: the camera's optical axis ends on the target.

The head's links are placed by the robot's kinematic model from the base pose in the
world while the joints are aimed, and only the result is set in the world; here the world
itself (PyBullet's link poses) judges where the camera points, for robots standing away
from the origin, turned, and with the torso raised.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from robocram.projection.neck import look_at
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World

CASES = [  # robot, base (x, y, yaw), joints set first, target in map
    ("pr2", (1.0, -0.5, 2.0), {"torso_lift_joint": 0.25}, (0.2, 0.4, 0.8)),
    ("pr2", (-0.3, 0.7, -1.0), {}, (0.5, 1.5, 0.2)),
    ("hsrb", (0.4, 0.2, 0.8), {"arm_lift_joint": 0.3}, (1.2, 1.0, 0.5)),
    # lift up: at 0 the HSR's base hull (it holds the column) meets the head turned up
    ("hsrb", (0.0, 0.0, -2.5), {"arm_lift_joint": 0.2}, (-0.8, -0.4, 1.1)),
]


@pytest.mark.parametrize(("robot", "base", "joints", "target"), CASES)
def test_the_optical_axis_ends_on_the_target(
    robot: str, base: tuple[float, float, float], joints: dict[str, float], target: tuple
) -> None:
    world = World()
    world.add_robot(robot, pose=Pose((base[0], base[1], 0.0), quat.from_euler(0, 0, base[2])))
    world.set_joint_states(robot, joints)
    projected = ProjectedRobot.of(world, robot)
    set_to = look_at(projected, target)
    desc = projected.description
    assert desc.pan_tilt is not None
    assert set(set_to) == {joint for joint, _ in desc.pan_tilt.axes()}
    frame = desc.cameras[0].frame
    optical = world.link_pose(robot, frame).matrix()
    to_target = np.asarray(target) - optical[:3, 3]
    off_axis = math.acos(min(1.0, float(optical[:3, 2] @ to_target / np.linalg.norm(to_target))))
    assert off_axis < 2e-4  # [rad]
    for joint, value in set_to.items():
        assert world.joint_states(robot)[joint] == value
    world.close()

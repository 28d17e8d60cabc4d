"""A neck arm wound up by the looks before parks and aims from there: Boxy's.

In a seeded household (activity_bench seed 1) Boxy's UR3 neck, after looks into the east
drawers, stood wound up (pan 2.23, lift -2.27 rad; parked 1.43, 0.39); IK seeded there
found for the look into the cups' drawer only goals with its forearm against the torso,
and the breakfast set 4 of 7 things. Judged in raw PyBullet: the camera's optical axis
points at the target, and no neck link touches the torso.
"""

from __future__ import annotations

import math

import numpy as np
import pybullet

from robocram.projection.neck import look_at
from robocram.projection.projected_robot import ProjectedRobot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

WOUND = (2.231, -2.274, -2.195, -2.438, 1.861, 2.932)  # [rad] as the looks before left it
STAND = Pose((0.4005, 0.5545, 0.0), quat.from_euler(0.0, 0.0, 1.1205))  # by the cups' drawer
INTO_DRAWER = (-0.2, 1.7, 0.7325)  # [m] the middle of the opened cups' drawer


def test_boxys_wound_up_neck_parks_and_looks_into_the_drawer() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        world.set_pose(scene.robot, STAND)
        world.set_joint_states(scene.robot, {"triangle_base_joint": -0.586})
        robot = ProjectedRobot.of(world, scene.robot)
        neck = robot.description.arms["neck"].joints
        world.set_joint_states(scene.robot, dict(zip(neck, WOUND, strict=True)))
        look_at(robot, INTO_DRAWER)
        body = world.object(scene.robot)
        camera = body.link_index[robot.description.cameras[0].frame]
        eye, turn = pybullet.getLinkState(body.body_id, camera, physicsClientId=cid)[4:6]
        axis = np.asarray(pybullet.getMatrixFromQuaternion(turn)).reshape(3, 3)[:, 2]
        towards = np.subtract(INTO_DRAWER, eye)
        angle = math.acos(float(axis @ towards) / float(np.linalg.norm(towards)))
        assert angle < math.radians(2.0)  # the optical axis (z) points at the target
        torso = body.link_index["torso_base_link"]
        for link in ("neck_forearm_link", "neck_wrist_1_link", "neck_wrist_2_link"):
            near = pybullet.getClosestPoints(
                body.body_id, body.body_id, 0.01, body.link_index[link], torso, physicsClientId=cid
            )
            assert all(point[8] > 0.0 for point in near), link  # apart from the torso
    finally:
        world.close()

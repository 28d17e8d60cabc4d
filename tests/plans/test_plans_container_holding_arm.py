"""An arm that holds something does not open or close a container: its hand would let go
of what it holds on the handle. Judged by raw PyBullet: the drawer's joint, and the mug
still where the right hand holds it."""

from __future__ import annotations

import math

import pybullet
import pytest

from robocram.plans import open_container
from robocram.plans.basic_actions import navigate, park_arms
from robocram.plans.errors import PlanSetupError
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import PoseStamped

DRAWER = "drawer_unit_drawer_3"
NORTH = (0.0, 0.0, math.sin(math.pi / 4), math.cos(math.pi / 4))


def _in_wrist(robot: int, wrist: int, mug: int, client: int) -> tuple[float, ...]:
    """The mug's position in the wrist's frame, from raw PyBullet."""
    link = pybullet.getLinkState(robot, wrist, physicsClientId=client)
    at, turned = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)
    back = pybullet.invertTransform(link[4], link[5])
    return tuple(pybullet.multiplyTransforms(back[0], back[1], at, turned)[0])


def test_the_free_arm_opens_the_drawer_and_the_holding_hand_keeps_its_mug() -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    cid = world.physics.client()
    try:
        bowl_x = world.pose("bowl-1").position[0]
        with simulated_robot(world, scene.robot):
            park_arms()
            navigate(PoseStamped("map", (bowl_x, 1.3, 0.0), NORTH))
            world.attach("mug-1", "pr2", "r_wrist_roll_link")  # the right hand holds it
            robot = world.object("pr2")
            wrist = robot.link_index["r_wrist_roll_link"]
            mug = world.object("mug-1").body_id
            gap = _in_wrist(robot.body_id, wrist, mug, cid)
            with pytest.raises(PlanSetupError, match="right arm holds 'mug-1'"):
                open_container(DRAWER, arm="right")
            opened = open_container(DRAWER)  # the left arm, the right one holding
        kitchen = world.object("kitchen")
        joint = kitchen.joint_index[f"{DRAWER}_joint"]
        assert pybullet.getJointState(kitchen.body_id, joint, cid)[0] == pytest.approx(
            opened, abs=0.005
        )
        assert opened > 0.3
        now = _in_wrist(robot.body_id, wrist, mug, cid)
        assert math.dist(gap, now) < 0.001  # still where the right hand holds it
    finally:
        world.close()

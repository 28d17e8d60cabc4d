"""`robot check` judges a camera an arm carries by where the arm points it.

Baxter's wrist camera, parked over its table, looks 60 degrees down (x share 0.24): it
looks ahead (the arm aims it), and it detects the mug where its axis meets the floor, not
1 m along it, under the floor. Parked looking up, it does not, and the fix names the arm.
PyBullet judges the axis: the camera link's z from its raw link state.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pybullet

from robocram.projection.projected_robot import ProjectedRobot
from robocram.robot_check import check_robot, description_from
from robocram.robot_check.head_checks import camera_forward
from robocram.robots import load_description
from robocram.world import World

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "robots"
CAMERA = "right_hand_camera_link"
LOOKING_UP = {"right_w1": 2.0}  # the wrist bent back: the camera's z 48 degrees up


def _raw_axis(world: World, robot: str) -> np.ndarray:
    """The camera link's z in the map, read from PyBullet's link state."""
    client, body = world.physics.client(), world.object(robot).body_id
    index = next(
        i
        for i in range(pybullet.getNumJoints(body, physicsClientId=client))
        if pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode() == CAMERA
    )
    turn = pybullet.getLinkState(body, index, physicsClientId=client)[5]
    return np.asarray(pybullet.getMatrixFromQuaternion(turn), float).reshape(3, 3)[:, 2]


def _parked(world: World) -> ProjectedRobot:
    desc = load_description(description_from(str(EXAMPLES / "baxter.py")))
    world.bodies.add_floor()
    robot = ProjectedRobot.of(world, world.add_robot(desc).name)
    world.set_joint_states(
        robot.name, {j: v for a in desc.arms.values() for j, v in a.parking.items()}
    )
    return robot


def test_a_wrist_camera_parked_looking_down_ahead_looks_ahead() -> None:
    world = World()
    try:
        robot = _parked(world)
        axis = _raw_axis(world, robot.name)
        assert 0.0 <= axis[0] < 0.5 and axis[2] < -0.5  # ahead-ish, steeply down
        result = camera_forward(robot)
        assert result.passed, result.detail
        assert f"{math.degrees(math.asin(-axis[2])):.0f} deg down" in result.detail
    finally:
        world.close()


def test_its_check_detects_the_mug_where_the_axis_meets_the_floor() -> None:
    """1 m along the axis lies under the floor: the mug stands where the axis meets it."""
    card = check_robot(description_from(str(EXAMPLES / "baxter.py")))
    detect = next(r for r in card.results if r.name == "detect")
    assert detect.passed, detect.detail
    seen = float(detect.detail.split()[-3])  # "saw robot_check_mug 0.31 m ahead"
    assert seen < 1.0


def test_a_wrist_camera_parked_looking_up_fails_naming_its_arm() -> None:
    world = World()
    try:
        robot = _parked(world)
        world.set_joint_states(robot.name, LOOKING_UP)
        assert _raw_axis(world, robot.name)[2] > 0.5
        result = camera_forward(robot)
        assert not result.passed
        assert "looks up" in result.detail and "right arm" in result.fix
    finally:
        world.close()

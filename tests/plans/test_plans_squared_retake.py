"""A carton lying turned on the table is taken again and put down square to the robot
(the clearing's last step before it gives a thing up), judged by raw PyBullet."""

from __future__ import annotations

import math

import pybullet

from robocram.plans.clearing_table import TableClearing, _squared
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from tests.milk_checks import TABLE_TOP, milk_on_its_spot

TURNED = math.radians(50.0)  # [rad] how Boxy's hand left the milk in households 2, 5, 9


def _yaw(q: tuple[float, ...]) -> float:
    return pybullet.getEulerFromQuaternion(q)[2]


def test_boxy_puts_a_turned_carton_down_square_to_its_base() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        with simulated_robot(world, scene.robot):
            table, lay = milk_on_its_spot(world, TURNED)
            x, y, _ = lay.position
            assert _squared("milk-1", "milk", "top", TableClearing(table))
        milk = world.object("milk-1").body_id
        robot = world.object(scene.robot).body_id
        (mx, my, _), milk_q = pybullet.getBasePositionAndOrientation(milk, cid)
        _, base_q = pybullet.getBasePositionAndOrientation(robot, cid)
        off = (_yaw(milk_q) - _yaw(base_q)) % (math.pi / 2)
        assert min(off, math.pi / 2 - off) < math.radians(3.0)  # square to the base
        assert math.hypot(mx - x, my - y) < 0.03  # where it lay
        low, _ = pybullet.getAABB(milk, physicsClientId=cid)
        assert abs(low[2] - TABLE_TOP) < 0.01  # on the table top
        assert not pybullet.getContactPoints(robot, milk, physicsClientId=cid)  # let go
    finally:
        world.close()

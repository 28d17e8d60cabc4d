"""Closing a container the arm cannot hold the handle of from any stand parks the neck and
tries again (``container_access.close_again``): the drafted Stretch's household 0 (session
31) cleared the table with the fridge open and, its head still turned down at the table's
milk, could not close it from the stand it had opened it from. The door's joint is judged
by raw PyBullet."""

from __future__ import annotations

from pathlib import Path

import pybullet

from robocram.designators import a
from robocram.execution import perform
from robocram.plans.container_access import close_again, open_from_front
from robocram.projection import simulated_robot
from robocram.world import World
from tests.plans.household_state import rebuilt

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
LOOKING_DOWN = [["joint_head_pan", -1.74], ["joint_head_tilt", -0.64]]  # at the table's milk


def _door(world: World) -> float:
    """The fridge door's joint [rad] by PyBullet."""
    uid, cid = world.object("kitchen").body_id, world.physics.client()
    index = next(
        j
        for j in range(pybullet.getNumJoints(uid, physicsClientId=cid))
        if pybullet.getJointInfo(uid, j, physicsClientId=cid)[1].decode() == "fridge_door_joint"
    )
    return float(pybullet.getJointState(uid, index, physicsClientId=cid)[0])


def test_the_stretch_closes_the_fridge_with_its_neck_parked() -> None:
    household = rebuilt(STRETCH, "stretch_table_set.json")
    world, robot = household.world, household.robot
    try:
        with simulated_robot(world, robot):
            opened = open_from_front("fridge_body")
            assert _door(world) > 1.3
            perform(a.motion(type="looking", configuration=LOOKING_DOWN))
            close_again(opened)
        assert abs(_door(world)) < 0.01
    finally:
        world.close()

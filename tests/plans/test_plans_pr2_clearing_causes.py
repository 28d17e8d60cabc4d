"""What stopped the PR2's clearing of household 14 (session 25), on its smallest case, judged
by raw PyBullet (the milk's bounds against the fridge's, what the hands touch, the door's
joint).
"""

from __future__ import annotations

import pybullet
import pytest

from robocram.plans.clearing_table import clear_table
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import FRIDGE_UPPER_SHELF, breakfast_scene
from robocram.tf import Pose

TABLE_TOP = 0.75  # [m] the kitchen table's top
# where setting the table for household 14 left the carton: on the table's middle line,
# turned -2.59 rad (taken by the hand facing the door, neither hand reached back by it)
MILK_14 = Pose((0.00064, -1.40278, 0.84961), (0.00015927, 0.0000093, 0.96228867, -0.27203031))


def test_the_pr2_lets_the_milk_go_under_the_fridge_shelf_and_takes_its_hand_back_out() -> None:
    """Its left hand, slanting past the open door at the edge of its reach, let the carton
    go on the shelf and could neither back off towards its wrist nor park, nor rise: the
    hand comes in level towards the base, the arm parks, and the fridge is closed again."""
    scene = breakfast_scene("pr2")
    world = scene.world
    cid = world.physics.client()
    try:
        world.set_pose("milk-1", MILK_14)
        with simulated_robot(world, scene.robot):
            done = clear_table(objects=["milk-1"])
        assert set(done.returned) == {"milk-1"}
        kitchen = world.object("kitchen")
        fridge_low, fridge_high = pybullet.getAABB(
            kitchen.body_id, kitchen.link_index["fridge_body"], cid
        )
        low, high = pybullet.getAABB(world.object("milk-1").body_id, physicsClientId=cid)
        for axis in (0, 1):  # inside the fridge's walls
            assert fridge_low[axis] < low[axis] and high[axis] < fridge_high[axis]
        assert high[2] < fridge_low[2] + FRIDGE_UPPER_SHELF  # under the upper shelf
        assert low[2] > TABLE_TOP + 0.2  # on the shelf below it, not on the floor
        robot = world.object(scene.robot).body_id
        milk = world.object("milk-1").body_id
        assert not pybullet.getContactPoints(robot, milk, physicsClientId=cid)  # let go
        assert not pybullet.getClosestPoints(robot, kitchen.body_id, 0.0, physicsClientId=cid)
        door = pybullet.getJointState(
            kitchen.body_id, kitchen.joint_index["fridge_door_joint"], cid
        )
        assert door[0] == pytest.approx(0.0, abs=0.01)  # closed again
    finally:
        world.close()

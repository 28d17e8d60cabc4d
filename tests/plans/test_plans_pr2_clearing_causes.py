"""What stopped the PR2's clearing of household 14 (session 25), on its smallest case, judged
by raw PyBullet (the milk's bounds against the fridge's, what the hands touch, the door's
joint).
"""

from __future__ import annotations

import pybullet

from robocram.plans.clearing_table import clear_table
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose
from tests.milk_checks import assert_milk_back_in_the_fridge

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
        assert_milk_back_in_the_fridge(world, scene.robot)
        robot, kitchen = world.object(scene.robot), world.object("kitchen")
        assert not pybullet.getClosestPoints(
            robot.body_id, kitchen.body_id, 0.0, physicsClientId=cid
        )
    finally:
        world.close()

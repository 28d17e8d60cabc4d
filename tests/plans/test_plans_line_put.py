"""A thing no usual put gets into a container is put from a stand on its approach line
(``plans/line_put.py``): the drafted Stretch gripped household 0's milk on the table but
every stand for the fridge collided with the fridge or the walls, and the carry height was
out of the lift's reach, so the milk went back on the table (session 31). The situation is
rebuilt from the state the household's setting left (tests/data/stretch_table_set.json),
the other things taken off the table as clearing had brought them back before the milk;
where the milk ends, and that the hand is off it, is judged by raw PyBullet."""

from __future__ import annotations

from pathlib import Path

import pybullet

from robocram.designators import an
from robocram.plans import perform
from robocram.projection import simulated_robot
from robocram.tf import Pose
from tests.plans.household_state import inside, rebuilt

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
FRIDGE = "fridge_body"
LET_GO = 0.05  # [m] the robot's nearest link is at least this far from the milk
OTHERS = ("bowl-1", "bowl-2", "cup-1", "cup-2", "spoon-1", "spoon-2")  # on the table too


def test_the_stretch_puts_the_milk_back_into_the_fridge() -> None:
    household = rebuilt(STRETCH, "stretch_table_set.json")
    world, robot = household.world, household.robot
    try:
        assert not inside(world, "milk-1", FRIDGE)
        for i, thing in enumerate(OTHERS):  # cleared before the milk, as in the household
            world.set_pose(thing, Pose((10.0 + i, 10.0, 0.05)))
        with simulated_robot(world, robot):
            perform(an.action(type="clearing-table", objects=["milk-1"]))
        assert inside(world, "milk-1", FRIDGE)
        cid = world.physics.client()
        milk, body = world.object("milk-1").body_id, world.object(robot).body_id
        assert pybullet.getClosestPoints(body, milk, LET_GO, physicsClientId=cid) == ()
        assert world.bodies.attachments(robot) == {}
    finally:
        world.close()

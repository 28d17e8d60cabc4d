"""A thing the clearing plan could not bring back does not stop it: the drafted Stretch's cup
beside the milk on the table (seeded household 13's places, session 32) could be delivered
neither into its drawer nor back where it was (every stand there meets the table or the
milk), so it stayed in the hand and the fridge could not be opened for the milk. Now it is
put down elsewhere on the table, the milk goes back, and a second round takes the cup again.
Where each thing ends is judged by raw PyBullet."""

from __future__ import annotations

import sys
from pathlib import Path

import pybullet
import pytest

from robocram.plans.clearing_table import clear_table
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World
from tests.milk_checks import assert_milk_back_in_the_fridge
from tests.plans.household_state import inside

sys.path.insert(0, str(Path(__file__).parents[2] / "benchmarks"))
from activity_bench import variant  # noqa: E402 - the bench's households

ROOT = Path(__file__).resolve().parents[2]
STRETCH = str(ROOT / "tests" / "data" / "stretch" / "stretch.py")
CUP_DRAWER = "east_drawers_1_drawer_3"  # where household 13 keeps its cups
# where setting the table for household 13 left them: the cup 0.14 m from the carton
CUP = Pose((0.14056, -1.35321, 0.79472), (-0.00142146, 0.00161591, 0.99862815, -0.05231807))
MILK = Pose((0.01424, -1.40971, 0.84953), (-7.5e-07, 2.01e-06, 0.9545439, 0.29807038))
START = Pose((2.0, 1.0, 0.0), quat.from_euler(0.0, 0.0, 0.0))  # by the east drawers


def _joint(world: World, joint: str) -> float:
    """The kitchen's ``joint`` [m | rad] by raw PyBullet."""
    kitchen, cid = world.object("kitchen"), world.physics.client()
    return float(pybullet.getJointState(kitchen.body_id, kitchen.joint_index[joint], cid)[0])


def test_the_stretch_puts_a_cup_it_could_not_bring_back_down_and_takes_it_again() -> None:
    kept, places = variant(13)
    scene = breakfast_scene(STRETCH, places=places, kept=kept)
    world = scene.world
    try:
        world.set_pose("cup-1", CUP)
        world.set_pose("milk-1", MILK)
        world.set_pose(scene.robot, START)
        with simulated_robot(world, scene.robot):
            done = clear_table(objects=["cup-1", "milk-1"])
        assert set(done.returned) == {"cup-1", "milk-1"}
        assert inside(world, "cup-1", CUP_DRAWER)
        assert_milk_back_in_the_fridge(world, scene.robot)
        cid, robot = world.physics.client(), world.object(scene.robot).body_id
        cup = world.object("cup-1").body_id
        assert not pybullet.getContactPoints(robot, cup, physicsClientId=cid)  # let go
        assert _joint(world, f"{CUP_DRAWER}_joint") == pytest.approx(0.0, abs=0.01)  # closed
    finally:
        world.close()

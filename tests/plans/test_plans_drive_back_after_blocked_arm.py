"""A differential base that drove for an arm motion whose path then was blocked goes back to
where it stood when a later drive finds no way from where it was left
(``projection/navigation.py`` ``_back_the_way_out``). The drafted Stretch's household 0
(session 31): clearing, at a stand south of the table for the milk's front grasp, IK moved
the base 0.13 m and turned it 31 degrees towards the table, the arm's path then met the
table's top, and the base stayed turned in the 0.65 m between the table and the south wall,
where no later drive found its way out (the fridge left open, both spoons left on the
table). The situation is rebuilt from the state the household left
(tests/data/stretch_table_set.json); the base is judged by raw PyBullet."""

from __future__ import annotations

import math
from pathlib import Path

import pybullet
import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import ManipulationPathBlocked
from robocram.plans.basic_actions import navigate
from robocram.projection import simulated_robot
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import World
from tests.plans.household_state import rebuilt, saved_pose

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
EAST = Pose((0.9, -0.5, 0.0), quat.from_euler(0.0, 0.0, math.pi))  # by the east counter:
# no path of 20,000 checks from where the arm motion's drive left the base, one from before


def _base(world: World, robot: str) -> tuple[float, float, float]:
    """The base's x, y [m] and yaw [rad] by PyBullet."""
    (x, y, _), orientation = pybullet.getBasePositionAndOrientation(
        world.object(robot).body_id, physicsClientId=world.physics.client()
    )
    return x, y, pybullet.getEulerFromQuaternion(orientation)[2]


def test_the_stretch_goes_back_the_way_out_after_its_arm_met_the_table_and_can_leave() -> None:
    household = rebuilt(STRETCH, "stretch_table_set.json")
    world, robot = household.world, household.robot
    try:
        start = _base(world, robot)
        target = PoseStamped.from_pose("map", saved_pose(household.state["target"]))
        with simulated_robot(world, robot):
            with pytest.raises(ManipulationPathBlocked) as blocked:
                perform(a.motion(type="moving-tcp", arm="arm", target=a.location(pose=target)))
            assert "kitchen/table_top" in str(blocked.value)
            x, y, yaw = _base(world, robot)
            assert math.hypot(x - start[0], y - start[1]) > 0.05  # left where IK drove it
            navigate(PoseStamped.from_pose("map", EAST))  # no way from there: back first
        x, y, _ = _base(world, robot)
        assert math.hypot(x - 0.9, y + 0.5) < 0.01
    finally:
        world.close()

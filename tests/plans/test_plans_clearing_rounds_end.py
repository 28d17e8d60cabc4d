"""Clearing the table ends when a round brings nothing back, also when what stopped it was
a container that would not open.

The drafted Stretch's household 13 cleared round after round for ever: the milk's return
had failed once (it was put back on the table), and from then on the fridge would not
open, so the milk was neither brought back nor counted as missed, and every round looked
like progress. Here the household changes under the PR2 as that one did: a lid is put
over the carton as the robot comes for it, and a box before the fridge once the first
round is over. The door is judged on raw PyBullet.
"""

from __future__ import annotations

import pybullet
import pytest

from robocram.execution import Task, TaskListener, TopLevel, listening
from robocram.execution.failures import NavigationPoseUnreachable
from robocram.plans.activity_failures import ActivityIncomplete
from robocram.plans.clearing_table import clear_table
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.world import World
from tests.plans.test_plans_pr2_clearing_causes import MILK_14

FRIDGE_BLOCKER = ((1.2, 0.7, 0.5), (0.55, 1.25, 0.25))  # [m] size, centre: before the fridge
LID = (0.16, 0.16, 0.12)  # [m] a box over the carton: no hand takes it


class ChangingHousehold(TaskListener):
    """Puts the lid on as the milk's return starts, blocks the fridge as the second round
    starts, and stops a clearing that goes round more than :data:`MAX_ROUNDS` times."""

    MAX_ROUNDS = 3

    def __init__(self, world: World) -> None:
        self.world = world
        self.rounds = 0

    def task_started(self, task: Task) -> None:
        world = self.world
        if task.name == "returning milk-1" and self.rounds == 0:
            x, y, z = world.pose("milk-1").position
            world.add_box("lid", LID, (x, y, z + 0.16))
        if task.name.startswith("clearing what was left"):
            self.rounds += 1
            assert self.rounds <= self.MAX_ROUNDS, "clearing went round and round"
            if self.rounds == 1:
                world.add_box("blocker", *FRIDGE_BLOCKER)


def _door(world: World) -> float:
    """The fridge door's joint value, read from PyBullet."""
    cid = world.physics.client()
    body = world.object("kitchen").body_id
    for j in range(pybullet.getNumJoints(body, physicsClientId=cid)):
        if pybullet.getJointInfo(body, j, physicsClientId=cid)[1] == b"fridge_door_joint":
            return float(pybullet.getJointState(body, j, physicsClientId=cid)[0])
    raise AssertionError("the kitchen has no fridge_door_joint")


def test_a_round_that_brings_nothing_back_ends_the_clearing() -> None:
    scene = breakfast_scene("pr2")
    world = scene.world
    try:
        world.set_pose("milk-1", MILK_14)
        household = ChangingHousehold(world)
        top = TopLevel("clearing")
        with (
            simulated_robot(world, scene.robot),
            listening(household),
            pytest.raises(ActivityIncomplete) as caught,
        ):
            top.run(clear_table, objects=["milk-1"])
        failure = caught.value
        assert failure.missing == ("milk-1",) and failure.done == ()
        # the second round's cause: the fridge would not open, the box was in the way
        assert any(
            isinstance(c, NavigationPoseUnreachable) and "blocker" in str(c)
            for c in failure.causes or ()
        )
        assert household.rounds == 1
        assert abs(_door(world)) < 0.02  # opened in the first round, closed again
    finally:
        world.close()

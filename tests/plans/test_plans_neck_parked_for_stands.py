"""Where no stand for opening a container was free, looking ahead too, the neck is parked
and the stands are tried once more (Boxy's household seed 46, session 29: clearing the
table, the milk to go back into the fridge; the neck, a UR arm carrying the camera, put
its links into the fridge, the counter or the cutlery unit at all six stands). The
situation is rebuilt from the state the household left (tests/data/boxy_fridge_neck.json);
the outcome is judged by raw PyBullet."""

from __future__ import annotations

import pybullet
import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import ProcessModuleInputError
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.container_access import open_from_front
from robocram.projection import simulated_robot
from robocram.robots.builtin import boxy
from robocram.world import World
from tests.plans.household_state import rebuilt


def _scene() -> tuple[World, str]:
    """The breakfast kitchen with Boxy, its neck and the things as the household had them."""
    household = rebuilt("boxy", "boxy_fridge_neck.json")
    return household.world, household.robot


def _bullet_joints(world: World, body: str) -> dict[str, float]:
    """Every joint's position by PyBullet."""
    uid, cid = world.object(body).body_id, world.physics.client()
    return {
        pybullet.getJointInfo(uid, j, physicsClientId=cid)[1].decode(): pybullet.getJointState(
            uid, j, physicsClientId=cid
        )[0]
        for j in range(pybullet.getNumJoints(uid, physicsClientId=cid))
    }


def _neck_touches(world: World, robot: str, other: str) -> list[str]:
    """The neck's links (named by PyBullet) nearer than 1 mm to ``other``."""
    uid, cid = world.object(robot).body_id, world.physics.client()
    links = {
        j: pybullet.getJointInfo(uid, j, physicsClientId=cid)[12].decode()
        for j in range(pybullet.getNumJoints(uid, physicsClientId=cid))
    }
    near = pybullet.getClosestPoints(uid, world.object(other).body_id, 0.001, physicsClientId=cid)
    return sorted({links[p[3]] for p in near if p[3] >= 0 and links[p[3]].startswith("neck")})


def test_boxy_parks_its_neck_and_opens_the_fridge_from_a_stand_it_had_refused() -> None:
    world, robot = _scene()
    try:
        log = AttemptLog()
        with simulated_robot(world, robot):
            opened = open_from_front("fridge_body", log)
        # all six stands refused twice (the neck as it was, then looking ahead); parked,
        # the first again, the second opened it
        tries = log.of("open")
        assert [x.failure is None for x in tries] == [False] * 13 + [True]
        x, y, _ = opened.stand.pose.position
        assert abs(x - 0.982) < 0.01 and abs(y - 0.9) < 0.01
        joints = _bullet_joints(world, robot)
        parking = boxy.description().neck_parking
        assert max(abs(joints[j] - v) for j, v in parking.items()) < 0.01
        assert _bullet_joints(world, "kitchen")["fridge_door_joint"] > 1.3  # of 1.40 rad
        assert _neck_touches(world, robot, "kitchen") == []
    finally:
        world.close()


def test_looking_with_a_configuration_of_other_joints_names_them() -> None:
    world, robot = _scene()
    try:
        before = _bullet_joints(world, robot)
        with simulated_robot(world, robot), pytest.raises(ProcessModuleInputError) as error:
            perform(a.motion(type="looking", configuration={"left_arm_0_joint": 0.3}))
        assert "left_arm_0_joint" in str(error.value)
        assert "neck_shoulder_pan_joint" in str(error.value)  # what it may give instead
        assert _bullet_joints(world, robot) == before
    finally:
        world.close()

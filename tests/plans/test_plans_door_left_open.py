"""A door a failed opening left mostly open is used as it is, and closed again.

The rolls on a handle no longer set the door and the robot back when the way back is
blocked (that was a jump no robot can make); Boxy's breakfast then left the fridge's door
at 1.18 of 1.40 rad, every stand in front of its handle was in the door's arc, the milk
could not go back, and the door stayed open. Here the PR2's arm opens the door part of the
way by real motions and then cannot go on (the opening fails with where it left the door):
the plan takes the door as open, from where the robot stands, and closing it again brings
it to 0 (raw PyBullet).
"""

from __future__ import annotations

import pybullet
import pytest

import robocram.plans.container_access as access
from robocram.execution.failures import EnvironmentManipulationImpossible
from robocram.plans.container_access import close_again, open_from_front
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene

DOOR = "fridge_door_joint"
PART_WAY = 1.2  # [rad] of 1.4: past OPEN_ENOUGH of the opening


def _door(cid: int, body: int) -> float:
    for j in range(pybullet.getNumJoints(body, physicsClientId=cid)):
        if pybullet.getJointInfo(body, j, physicsClientId=cid)[1].decode() == DOOR:
            return float(pybullet.getJointState(body, j, physicsClientId=cid)[0])
    raise AssertionError(f"no {DOOR}")


def test_a_door_left_mostly_open_is_used_and_closed_again(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    scene = breakfast_scene("pr2")
    world = scene.world
    real_open = access.open_container
    calls: list[str | None] = []

    def opens_part_way(name: str, arm: str | None = None) -> float:
        calls.append(arm)
        if len(calls) == 1:
            real_open(name, angle=PART_WAY, arm=arm)  # the arm's rolls got this far
        raise EnvironmentManipulationImpossible(
            "the arm cannot go on", reached=world.joint_states("kitchen")[DOOR]
        )

    monkeypatch.setattr(access, "open_container", opens_part_way)
    cid = world.physics.client()
    kitchen = world.object("kitchen").body_id
    try:
        with simulated_robot(world, scene.robot):
            opened = open_from_front("fridge_body")
            left = _door(cid, kitchen)
            stands = pybullet.getBasePositionAndOrientation(
                world.object("pr2").body_id, physicsClientId=cid
            )[0]
            monkeypatch.setattr(access, "open_container", real_open)
            close_again(opened)
        assert calls == [opened.stand.arm] * 2  # then once more from where it stood
        assert left == pytest.approx(PART_WAY, abs=1e-6)  # not set back, not set on
        assert opened.reached is not None
        assert opened.reached.position[:2] == pytest.approx(stands[:2], abs=1e-6)
        assert _door(cid, kitchen) == pytest.approx(0.0, abs=1e-6)
    finally:
        world.close()

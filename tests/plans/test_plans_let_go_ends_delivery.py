"""A put that let the thing go and failed ends the delivery: no other stand or spot is
tried with an empty hand (Boxy's let-go bowl, session 27, drove on with its hand in the
drawer). Judged by raw PyBullet: where the mug lies, and that the robot did not move."""

from __future__ import annotations

import pybullet
import pytest

from robocram.execution.failures import NavigationPoseUnreachable, ObjectUndeliverable
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.deliver import deliver
from robocram.plans.errors import ObjectLetGo
from robocram.plans.fetch import fetch
from robocram.plans.grasp_failures import PlacingFailed
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose

DROP = 0.15  # [m] the put's target over where the mug stood: let go there, it falls


def test_a_put_that_let_the_mug_fall_ends_the_delivery_at_once() -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    cid = world.physics.client()
    mug = world.object("mug-1").body_id
    robot = world.object(scene.robot).body_id
    try:
        (x, y, z), turn = pybullet.getBasePositionAndOrientation(mug, physicsClientId=cid)
        log = AttemptLog()
        with simulated_robot(world, scene.robot):
            held = fetch("mug", log=log)
            with pytest.raises(ObjectLetGo) as caught:
                deliver(held, Pose((x, y, z + DROP), turn), log=log)
            failure = caught.value
            assert isinstance(failure, ObjectUndeliverable)
            assert failure.object_name == "mug-1"
            assert failure.causes is not None
            assert isinstance(failure.causes[-1], PlacingFailed)
            assert "after letting go" in str(failure.causes[-1])
            placings = [
                t for t in log.of("deliver") if not isinstance(t.failure, NavigationPoseUnreachable)
            ]
            assert len(placings) == 1  # the one put that let it go: no other stand
            lay = pybullet.getBasePositionAndOrientation(mug, physicsClientId=cid)[0]
            assert lay[2] < z + DROP - 0.05  # it fell from where it was let go
            joints = range(pybullet.getNumJoints(robot, physicsClientId=cid))
            before = pybullet.getJointStates(robot, list(joints), physicsClientId=cid)
            base = pybullet.getBasePositionAndOrientation(robot, physicsClientId=cid)
            with pytest.raises(ObjectLetGo):  # given again: refused before any motion
                deliver(held, Pose((x, y, z + DROP), turn), log=log)
            after = pybullet.getJointStates(robot, list(joints), physicsClientId=cid)
            assert [s[0] for s in after] == [s[0] for s in before]
            assert pybullet.getBasePositionAndOrientation(robot, physicsClientId=cid) == base
    finally:
        world.close()

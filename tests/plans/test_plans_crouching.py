"""A plan knows its robot crouches from the knowledge base, and a crouched step stands up.

Why: a legged robot whose handle holds or picks are out of reach standing tries them again
crouched (TALOS and the bowl's drawer, issue 37), and stands up before it drives on. The
body's height is judged on raw PyBullet (its base's frame, the soles by its own forward
kinematics).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.execution.failures import ManipulationPoseUnreachable, TorsoGoalUnreachable
from robocram.plans.crouching import can_crouch, crouched, crouched_at_stand
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from tests.bullet_links import link_frame

TALOS = Path(__file__).parents[2] / "examples" / "robots" / "talos.py"


def test_talos_crouches_inside_and_stands_up_after_the_pr2_cannot() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(str(TALOS))
    world, robot = scene.world, scene.robot
    client, body = world.physics.client(), world.object(robot).body_id

    def root() -> np.ndarray:
        return np.asarray(pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0])

    try:
        with simulated_robot(world, robot):
            assert can_crouch()
            standing, sole = root(), link_frame(body, client, "left_sole_link")[0]
            with crouched(0.2):
                assert root() - standing == pytest.approx((0.0, 0.0, -0.2), abs=1e-6)
                assert link_frame(body, client, "left_sole_link")[0] == pytest.approx(
                    sole, abs=1e-4
                )
            assert root() == pytest.approx(standing, abs=1e-6)
            deeper = crouched(1.5)  # deeper than its legs bend: nothing moves
            with pytest.raises(TorsoGoalUnreachable, match="cannot crouch 1.500"), deeper:
                pass
            assert root() == pytest.approx(standing, abs=1e-6)
    finally:
        world.close()
    pr2 = tabletop_scene("pr2")
    try:
        with simulated_robot(pr2.world, pr2.robot):
            assert not can_crouch()
    finally:
        pr2.world.close()


def test_a_pick_crouched_at_its_stand_stands_up_after_its_arms_parked_if_it_failed() -> None:
    """A fetch crouches at each stand (``fetch(depth=...)``): a pick that failed there may
    leave a hand out over the thing, so the arms are parked before it stands up; one that
    held the thing stands up holding it, the arm where it is (Centauro, zoo37)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(str(TALOS))
    world, robot = scene.world, scene.robot
    client, body = world.physics.client(), world.object(robot).body_id
    indices = {
        pybullet.getJointInfo(body, i, physicsClientId=client)[1].decode(): i
        for i in range(pybullet.getNumJoints(body, physicsClientId=client))
    }
    parking = dict(world.robot(robot).description.arms["left"].parking)
    out = {joint: value + 0.3 for joint, value in parking.items()}  # a hand held out

    def root_z() -> float:
        return float(pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0][2])

    def arm() -> list[float]:
        return [pybullet.getJointState(body, indices[j], physicsClientId=client)[0] for j in out]

    try:
        with simulated_robot(world, robot):
            world.set_joint_states(robot, parking)
            standing = root_z()
            with pytest.raises(ManipulationPoseUnreachable), crouched_at_stand(0.2):
                assert root_z() == pytest.approx(standing - 0.2, abs=1e-6)
                world.set_joint_states(robot, out)
                raise ManipulationPoseUnreachable("no pick here")
            assert root_z() == pytest.approx(standing, abs=1e-6)
            assert arm() == pytest.approx(list(parking.values()), abs=1e-3)
            with crouched_at_stand(0.2):
                world.set_joint_states(robot, out)
                held_out = arm()  # within its limits
            assert root_z() == pytest.approx(standing, abs=1e-6)
            assert arm() == pytest.approx(held_out, abs=1e-6)
            assert max(abs(a - b) for a, b in zip(held_out, parking.values(), strict=True)) > 0.2
    finally:
        world.close()

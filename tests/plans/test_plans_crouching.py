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

from robocram.execution.failures import TorsoGoalUnreachable
from robocram.plans.crouching import can_crouch, crouched
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

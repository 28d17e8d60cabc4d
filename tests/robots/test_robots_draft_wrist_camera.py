"""A camera found on an arm's wrist rides on that arm: the Donbot's UR5 is no neck too.

The Donbot's camera sits on its UR5's wrist. The draft described the UR5 twice, as its
arm and as a neck arm aiming the camera; as a neck, the camera's heights were those of the
neck's parking (0.63 m, under every kitchen counter) and a look moved it 0.15 m at most,
so the kitchen search saw no mug. Now the arm carries the camera as a named camera's
carrier does: parked to look, raised when it looks. A mug at the point looked at is what
the look is for, not what hides it: the tabletop pick-up lifts it (raw PyBullet).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from tests.drafts import drafted_module

DONBOT = Path(__file__).resolve().parents[1] / "data" / "zoo" / "iai_donbot" / "iai_donbot.urdf"


@pytest.fixture(scope="module")
def donbot(tmp_path_factory: pytest.TempPathFactory) -> Path:
    module = tmp_path_factory.mktemp("donbot") / "iai_donbot.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(DONBOT, module)
    return module


def test_the_wrist_camera_rides_on_the_arm_parked_to_look(donbot: Path) -> None:
    text = donbot.read_text("utf-8")
    assert "neck_arm=" not in text and '"neck": ArmDescription' not in text
    assert "it carries the camera" in text
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(str(donbot))
    world = scene.world
    try:
        client, body = world.physics.client(), world.object(scene.robot).body_id
        links = {
            pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i
            for i in range(pybullet.getNumJoints(body, physicsClientId=client))
        }
        camera = pybullet.getLinkState(body, links["camera_link"], physicsClientId=client)[4]
        shoulder = pybullet.getLinkState(body, links["ur5_base_link"], physicsClientId=client)[4]
    finally:
        world.close()
    assert camera[2] > shoulder[2] + 0.1  # the parked wrist holds the camera over the shoulder


def test_the_donbot_lifts_the_mug_it_looked_at(donbot: Path) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(str(donbot))
    world = scene.world
    try:
        client = world.physics.client()
        mug = world.object("mug-1").body_id
        before = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)[0]
        with simulated_robot(world, scene.robot):
            pick_up(scene.look_target)
        after = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)[0]
    finally:
        world.close()
    assert after[2] > before[2] + 0.03  # lifted off the table

"""A robot built on a table works on it: Tracy's fixed camera looks down onto its own top.

Tracy (tests/data/zoo, drafted): two arms on a table, a camera on a pole looking 72
degrees down onto it. `robot check` takes that camera as looking ahead (down onto what lies
ahead) and puts its probe mug on the table where the optical axis meets it; the tabletop
scene lays its mug there and adds no table, and the pick-up lifts it, its IK not counting
the mug resting on the robot's own top as a collision. The workcell, whose table cannot
stand there, says so. Judged by PyBullet: a ray down onto the mug's spot meets the robot's
own link, and the mug rises.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.robot_check import check_robot, description_from
from robocram.robots import draft_description
from robocram.scenes import UnfitRobotError, tabletop_scene, workcell_scene

TRACY = Path(__file__).resolve().parents[1] / "data" / "zoo" / "tracy" / "tracy.urdf"
LIFTED = 0.03  # [m] the mug rises at least this much


@pytest.fixture(scope="module")
def tracy(tmp_path_factory: pytest.TempPathFactory) -> str:
    module = tmp_path_factory.mktemp("tracy") / "tracy.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        module.write_text(draft_description(TRACY).source(module), "utf-8")
    return str(module)


def test_its_check_passes_with_the_camera_looking_down_onto_its_table(tracy: str) -> None:
    card = check_robot(description_from(tracy))
    assert card.passed, card.failures()
    ahead = next(r for r in card.results if r.name.endswith("looks ahead"))
    assert "down onto what lies ahead" in ahead.detail


def test_its_mug_lies_on_its_own_top_and_it_lifts_it(tracy: str) -> None:
    scene = tabletop_scene(description_from(tracy))
    world = scene.world
    try:
        client, body = world.physics.client(), world.object(scene.robot).body_id
        mug = world.object("mug-1").body_id
        assert "table" not in {o.name for o in world.objects()}
        start, _ = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)
        pybullet.resetBasePositionAndOrientation(
            mug, (start[0], start[1], 5.0), (0, 0, 0, 1), physicsClientId=client
        )  # out of the way of the ray, then back
        hit = pybullet.rayTest(
            (start[0], start[1], 3.0), (start[0], start[1], 0.0), physicsClientId=client
        )[0]
        pybullet.resetBasePositionAndOrientation(mug, start, (0, 0, 0, 1), physicsClientId=client)
        assert hit[0] == body and hit[3][2] == pytest.approx(start[2], abs=0.005)
        with simulated_robot(world, scene.robot):
            pick_up(scene.look_target)
        end, _ = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)
        assert end[2] > start[2] + LIFTED
    finally:
        world.close()


def test_its_workcell_says_no_table_can_stand_on_its_top(tracy: str) -> None:
    with pytest.raises(UnfitRobotError, match="its own top"):
        workcell_scene(description_from(tracy))

"""A kitchen of more links than one PyBullet body holds runs the transport (issue 37).

tests/data/big_kitchen/big_kitchen.urdf is robocram's kitchen with a west counter run of
five four-drawer units and five wall cupboards (``tools/make_kitchen_urdf.py --big``, 140
links). It loads as several bodies (``world/body_loading.py``); the kept description is
the fresh draft with one edit, where mugs and bowls are kept. The bowl's drawer belongs
to a unit that is a body of its own.
"""

from __future__ import annotations

import difflib
import math
from pathlib import Path

import pytest

from robocram.designators import a
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.robots import RobotModel
from robocram.scenes import draft_environment, environment_scene
from robocram.scenes.environment_check import check_environment, environment_from
from robocram.scenes.environment_scene import ItemPlace
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world.robot_urdf import MAX_LINKS

BIG = Path(__file__).resolve().parents[1] / "data" / "big_kitchen"
DRAWER = "west_drawers_1_drawer_4"


def test_the_kept_draft_is_one_edit_from_a_fresh_one_and_passes_the_check() -> None:
    kept = BIG / "big_kitchen_env.py"
    fresh = draft_environment(BIG / "big_kitchen.urdf").source(kept)
    matcher = difflib.SequenceMatcher(
        None, fresh.splitlines(), kept.read_text("utf-8").splitlines(), autojunk=False
    )
    assert sum(tag != "equal" for tag, *_ in matcher.get_opcodes()) == 1  # usual places
    assert len(RobotModel.from_file(BIG / "big_kitchen.urdf").joints) > MAX_LINKS
    card = check_environment(environment_from(kept))
    assert card.passed, card.render()
    assert any(DRAWER in line.part for line in card.lines)


def test_the_pr2_carries_the_mug_and_the_bowl_from_its_drawer_to_the_table() -> None:
    items = [
        ItemPlace("mug-1", "mug", "counter_top_west", (0.1, 0.3)),
        ItemPlace("bowl-1", "bowl", DRAWER, (-0.26, 0.0)),
    ]
    start = Pose((-1.0, 0.0, 0.0), quat.from_euler(0.0, 0.0, math.pi))
    scene = environment_scene(environment_from(BIG / "big_kitchen_env.py"), "pr2", items, start)
    world, env = scene.world, scene.environment
    try:
        assert len(world.object(env).bodies) > 1
        with simulated_robot(world, scene.robot):
            for item in ("mug", "bowl"):
                transport(item, a.location(on=(env, "table_top"), for_=f"{item}-1"))
        for item in ("mug-1", "bowl-1"):
            assert world.aabb(item)[0][2] == pytest.approx(0.75, abs=0.02)
            assert "table_top" in {p.link_b for p in world.contacts.contact_points(item, env)}
        assert world.joint_states(env)[f"{DRAWER}_joint"] == pytest.approx(0.0, abs=0.01)
    finally:
        world.close()

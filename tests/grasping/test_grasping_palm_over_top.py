"""Issue 37: a palm hand's side grasp is not raised over the body's top.

A palm hand held sideways is raised until its row keeps 1 cm over the body's bottom.
Rollin' Justin's open hand reaches 106 mm across its row on the thumb's side and 91 mm on
the other: turned thumb down, its handle grasp of the 106 mm mug rose 63 mm and its tool
frame (amid the closing fingers) stood 22 mm over the mug's top, so the left hand closed
on nothing (``GripperMetOneSide``, then ``GripperClosedCompletely``). Such a grasp is no
longer offered; the other turn (raised 48 mm) is. Judged on PyBullet's box of the mug.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.plans.known_robot import current_robot
from robocram.plans.pick_object import grasp_choices
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from tests.drafts import drafted_module

JUSTIN = (
    Path(__file__).resolve().parents[1] / "data" / "zoo" / "rollin_justin" / "rollin_justin.urdf"
)


def test_justins_handle_grasps_close_below_the_mugs_top(tmp_path: Path) -> None:
    module = drafted_module(JUSTIN, tmp_path / "rollin_justin.py")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(str(module))
    world = scene.world
    try:
        with simulated_robot(world, scene.robot):
            robot = current_robot()
            heights = {
                arm: [
                    c.grasp_pose.pose.position[2]
                    for c in grasp_choices(robot, "mug-1", arm, "handle")
                ]
                for arm in ("left", "right")
            }
        body = world.object("mug-1").body_id
        low, high = pybullet.getAABB(body, physicsClientId=world.physics.client())
    finally:
        world.close()
    for arm, tools in heights.items():
        assert tools, f"{arm}: a handle grasp offered"
        # each tool frame, where the fingers close, within the mug's height, 17 mm under its
        # top (the thumb-down turn's stood 22 mm over it: 1.288 m)
        for tool in tools:
            assert low[2] < tool < high[2] - 0.01, (arm, tools, low[2], high[2])
            assert tool == pytest.approx(1.249, abs=0.002)

"""A grasp round the whole object a finger was caught at is tried again, after every other,
with the hand opened half way.

The drafted Stretch's fingers, fully open, reach 13 cm either side of the tool. In
household seed 0 of ``benchmarks/activity_bench.py`` cup-2 stands 4 cm from the west wall
of its opened drawer, under the counter top's edge: from where it first stood every grasp
failed (the open fingers closing along the drawer met the counter top over it; closing
across it, the outer fingertip slid down outside the drawer's side wall and met it when
the grip closed). Opened half way, the hand takes cup-2 from above. Judged on raw
PyBullet: cup-2 is lifted clear of the drawer's top, and cup-1 has not moved.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pybullet
import pytest

from robocram.plans.containers import container
from robocram.plans.pick_object import pick_up_object
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import BREAKFAST_PLACES, breakfast_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
CUPS = "cutlery_unit_drawer_4"
SEED_0 = {"cup-1": (-0.2432, 0.18), "cup-2": (-0.2496, -0.18)}  # [m] in the drawer
STAND = Pose((-0.267, 1.1963, 0.0), quat.from_euler(0.0, 0.0, -2.9439))  # where it peered in
STILL = 0.005  # [m] cup-1 moved no more than this


def test_a_caught_top_grasp_takes_the_cup_with_the_hand_opened_half_way() -> None:
    places = [replace(p, xy=SEED_0[p.name]) if p.name in SEED_0 else p for p in BREAKFAST_PLACES]
    scene = breakfast_scene(STRETCH, places=places)
    world = scene.world
    cid = world.physics.client()
    kitchen = world.object("kitchen")
    drawer = kitchen.link_index[CUPS]
    try:
        with simulated_robot(world, scene.robot):
            opened = container(CUPS).opened
        before = pybullet.getLinkState(kitchen.body_id, drawer, physicsClientId=cid)[4]
        world.set_joint_states("kitchen", {f"{CUPS}_joint": opened})
        after = pybullet.getLinkState(kitchen.body_id, drawer, physicsClientId=cid)[4]
        for cup in SEED_0:  # carried out with the drawer
            at = world.pose(world.object(cup))
            moved = tuple(p + a - b for p, a, b in zip(at.position, after, before, strict=True))
            world.set_pose(cup, Pose(moved, at.orientation))
        cup_1 = pybullet.getBasePositionAndOrientation(world.object("cup-1").body_id, cid)[0]
        world.set_pose(scene.robot, STAND)
        with simulated_robot(world, scene.robot):
            held = pick_up_object("cup-2", out_of=("kitchen", CUPS))
        assert held.grasp == "top"
        top = pybullet.getAABB(kitchen.body_id, drawer, cid)[1][2]
        low = pybullet.getAABB(world.object("cup-2").body_id, physicsClientId=cid)[0][2]
        assert low > top  # lifted out of the drawer
        now = pybullet.getBasePositionAndOrientation(world.object("cup-1").body_id, cid)[0]
        assert now == pytest.approx(cup_1, abs=STILL)
    finally:
        world.close()

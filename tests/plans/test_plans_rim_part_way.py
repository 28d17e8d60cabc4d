"""A rim grasp a finger was caught at is tried again, after every other, with the hand
opened a third only.

The drafted Stretch's fingers, fully open, span 12 cm. In household seed 0 of
``benchmarks/activity_bench.py`` the bowls lie 1 cm nearer the front of their opened
drawer than in the default kitchen: every rim grasp of bowl-2 put the outer finger into
bowl-1 or the drawer's front (IK solutions refused for a fingertip, a grip met bowl-1 on
one side), and neither bowl was set. Opened a third, the hand takes bowl-2 from where it
first stood. Judged on raw PyBullet: bowl-2 is lifted clear of the drawer's top, and
bowl-1 has not moved.
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
BOWLS = "drawer_unit_drawer_3"
SEED_0 = {"bowl-1": (-0.2462, 0.12), "bowl-2": (-0.2497, -0.12)}  # [m] in the drawer
STAND = Pose((-1.49, 1.059, 0.0), quat.from_euler(0.0, 0.0, 3.1416))  # where it peered in
STILL = 0.005  # [m] bowl-1 moved no more than this


def test_a_caught_rim_grasp_takes_the_bowl_with_the_hand_opened_part_way() -> None:
    places = [replace(p, xy=SEED_0[p.name]) if p.name in SEED_0 else p for p in BREAKFAST_PLACES]
    scene = breakfast_scene(STRETCH, places=places)
    world = scene.world
    cid = world.physics.client()
    kitchen = world.object("kitchen")
    drawer = kitchen.link_index[BOWLS]
    try:
        with simulated_robot(world, scene.robot):
            opened = container(BOWLS).opened
        before = pybullet.getLinkState(kitchen.body_id, drawer, physicsClientId=cid)[4]
        world.set_joint_states("kitchen", {f"{BOWLS}_joint": opened})
        after = pybullet.getLinkState(kitchen.body_id, drawer, physicsClientId=cid)[4]
        for bowl in SEED_0:  # carried out with the drawer
            at = world.pose(world.object(bowl))
            moved = tuple(p + a - b for p, a, b in zip(at.position, after, before, strict=True))
            world.set_pose(bowl, Pose(moved, at.orientation))
        bowl_1 = pybullet.getBasePositionAndOrientation(world.object("bowl-1").body_id, cid)[0]
        world.set_pose(scene.robot, STAND)
        with simulated_robot(world, scene.robot):
            held = pick_up_object("bowl-2", out_of=("kitchen", BOWLS))
        assert held.grasp == "rim"
        top = pybullet.getAABB(kitchen.body_id, drawer, cid)[1][2]
        low = pybullet.getAABB(world.object("bowl-2").body_id, physicsClientId=cid)[0][2]
        assert low > top  # lifted out of the drawer
        now = pybullet.getBasePositionAndOrientation(world.object("bowl-1").body_id, cid)[0]
        assert now == pytest.approx(bowl_1, abs=STILL)
    finally:
        world.close()

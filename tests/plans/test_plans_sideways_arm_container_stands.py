"""Stands in front of an opened container face its front with the arm that works there:
the Stretch's arm works sideways, and its stands for the milk in the opened fridge were
beside the fridge's side wall, where every ray to the milk met the wall (session 28).
Judged by raw PyBullet: the fridge's bounds."""

from __future__ import annotations

import itertools
from pathlib import Path

import pybullet

from robocram.designators import an
from robocram.plans.container_access import OpenedContainer
from robocram.plans.containers import container
from robocram.plans.fetch import _stands
from robocram.plans.stands import HandleStand, planar_pose
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import PoseStamped

STRETCH = Path(__file__).parents[1] / "data" / "stretch" / "stretch.py"
OPENED_FROM = planar_pose(0.686, 1.0, 3.14159)  # its arm (working 90 degrees right) at the door


def test_the_stretch_stands_for_the_fridge_s_milk_face_the_fridge_s_front() -> None:
    scene = breakfast_scene(str(STRETCH))
    world = scene.world
    cid = world.physics.client()
    try:
        kitchen = world.object("kitchen")
        low, high = pybullet.getAABB(
            kitchen.body_id, kitchen.link_index["fridge_body"], physicsClientId=cid
        )
        where = PoseStamped.from_pose("map", world.pose("milk-1"))
        with simulated_robot(world, scene.robot):
            opened = OpenedContainer(container("fridge_body"), HandleStand(OPENED_FROM, "arm"))
            seen = an.object(type="milk", name="milk-1")
            stands = list(itertools.islice(_stands(seen, where, None, opened, []), 5))
        assert stands
        for pose, _arm in stands:
            x, y, _ = pose.position
            assert y < low[1]  # in front of the fridge (its front faces -y), not beside it
            assert low[0] - 0.3 < x < high[0] + 0.3
    finally:
        world.close()

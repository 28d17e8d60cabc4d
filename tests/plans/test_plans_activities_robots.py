"""Breakfast on the other robots: what works, and what stops it, found and named.

Each test asks what the PR2's test asks, judged by raw PyBullet (the joint of the drawer
opened, the things' bodies on the table); one that fails says its cause in a strict xfail.
"""

from __future__ import annotations

from pathlib import Path

import pybullet
import pytest

from robocram.designators import an
from robocram.plans import perform
from robocram.plans.container_access import open_from_front
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene

FETCH = str(Path(__file__).resolve().parents[1] / "data" / "fetch" / "fetch.py")
BOWLS = "drawer_unit_drawer_3"
TABLE_TOP = 0.75  # [m] the kitchen table's top


def test_the_hsr_sets_the_table_for_two() -> None:
    scene = breakfast_scene("hsrb")
    world = scene.world
    try:
        with simulated_robot(world, scene.robot):
            perform(an.action(type="setting-table", people=2))
        for name in ("bowl-1", "bowl-2", "cup-1", "cup-2", "spoon-1", "spoon-2", "milk-1"):
            low, _ = pybullet.getAABB(
                world.object(name).body_id, physicsClientId=world.physics.client()
            )
            assert low[2] == pytest.approx(TABLE_TOP, abs=0.01), name
        body = world.object("kitchen")
        for joint in ("drawer_unit_drawer_3_joint", "fridge_door_joint"):
            closed = pybullet.getJointState(
                body.body_id, body.joint_index[joint], physicsClientId=world.physics.client()
            )[0]
            assert closed == pytest.approx(0.0, abs=0.01), joint
    finally:
        world.close()


def test_the_drafted_fetch_opens_the_bowls_drawer() -> None:
    scene = breakfast_scene(FETCH)
    world = scene.world
    try:
        with simulated_robot(world, scene.robot):
            open_from_front(BOWLS)
        body = world.object("kitchen")
        index = body.joint_index[f"{BOWLS}_joint"]
        opened = pybullet.getJointState(
            body.body_id, index, physicsClientId=world.physics.client()
        )[0]
        assert opened == pytest.approx(0.4, abs=0.01)
    finally:
        world.close()

"""A transport puts the thing down from a stand the arm reaches the spot from, when no
stand holding it over the spot as the arm holds it now will do: Centauro held the mug at
its side too high for its arm to lower it there, and stands nearer met the table with its
hips."""

from __future__ import annotations

import sys
from collections.abc import Iterator

import pytest

from robocram.designators import a
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.world.pybullet_backend import pybullet
from tests.bullet_links import link_indices


def test_the_mug_goes_down_from_a_reaching_stand_when_no_holding_stand_fits(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    def no_stand(*_: object) -> Iterator[Pose]:
        return iter(())  # every stand holding it over the spot meets the table

    monkeypatch.setattr(sys.modules["robocram.plans.deliver"], "placing_stands", no_stand)
    scene = kitchen_scene("pr2")
    try:
        with simulated_robot(scene.world, scene.robot):
            transport("mug", a.location(on=("kitchen", "table_top"), for_="mug-1"))
        client = scene.world.physics.client()
        kitchen = scene.world.object("kitchen").body_id
        table = link_indices(kitchen, client)["table_top"]
        (tx0, ty0, _), (tx1, ty1, top) = pybullet.getAABB(kitchen, table, physicsClientId=client)
        mug = scene.world.object("mug-1").body_id
        (mx0, my0, bottom), (mx1, my1, _) = pybullet.getAABB(mug, physicsClientId=client)
        assert bottom == pytest.approx(top, abs=0.02)  # standing on the table's top
        assert tx0 <= (mx0 + mx1) / 2 <= tx1 and ty0 <= (my0 + my1) / 2 <= ty1
        assert scene.world.bodies.attached_to("mug-1") is None  # let go
    finally:
        scene.world.close()

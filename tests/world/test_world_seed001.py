"""Seed 001 of CRAM's reasoning tutorial: a pot out of view, raised into view, falling to rest."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.tf import Pose
from robocram.world import World, WorldObject

TABLE_TOP = 1.0  # [m]
POT_HEIGHT = 0.15  # [m] of the catalogue pot


@pytest.fixture(scope="module")
def scene() -> Iterator[tuple[World, dict[str, WorldObject]]]:
    world = World()
    world.bodies.add_floor()
    pr2 = world.add_robot("pr2", pose=Pose((0, 0, 0)))
    world.set_joint_states(pr2, {"torso_lift_joint": 0.3, "head_tilt_joint": 0.4})
    objects = {
        "pr2": pr2,
        "table": world.add_box("table", (0.7, 1.5, TABLE_TOP), Pose((1.6, 0, TABLE_TOP / 2))),
        "pot": world.add_item("pot-1", "pot", Pose((2.1, 0, 0.3))),
        "mug-1": world.add_item("mug-1", "mug", ((1.5, 0.4, TABLE_TOP), (0, 0, 0, 1))),
        "mug-2": world.add_item("mug-2", "mug", ((1.5, -0.4, TABLE_TOP), (0, 0, 0, 1))),
    }
    yield world, objects
    world.close()


@pytest.mark.parametrize("method", ["ray", "render"])
def test_pot_behind_the_table_is_hidden_by_it(scene, method) -> None:
    world, o = scene
    assert not world.view.visible(o["pr2"], o["pot"], method=method)
    assert world.view.visibility_fraction(o["pr2"], o["pot"], method=method) < 0.05
    assert world.view.occluding_objects(o["pr2"], o["pot"], method=method) == [o["table"]]


def test_raised_pot_is_visible_then_falls_and_rests_on_the_table(scene) -> None:
    world, o = scene
    world.set_pose(o["pot"], Pose((1.6, 0, 1.4)))
    assert world.view.visible(o["pr2"], o["pot"], method="ray")
    assert world.view.visible(o["pr2"], o["pot"], method="render")
    assert not world.contacts.contact(o["pot"], o["table"])
    assert not world.physics.stable(o["pot"])  # it is in mid-air
    world.physics.simulate(2.0)
    x, y, z = world.pose(o["pot"]).position
    assert z == pytest.approx(TABLE_TOP + POT_HEIGHT / 2, abs=0.01)
    assert (x, y) == pytest.approx((1.6, 0.0), abs=0.02)
    assert world.contacts.contact(o["pot"], o["table"])
    assert world.physics.supported_by(o["pot"], o["table"])
    assert not world.physics.supported_by(o["table"], o["pot"])
    assert world.physics.above(o["pot"], o["table"]) and world.physics.below(o["table"], o["pot"])
    assert world.physics.stable(o["pot"])
    assert world.physics.stable()  # the mugs too
    assert world.view.visible(o["pr2"], o["pot"])

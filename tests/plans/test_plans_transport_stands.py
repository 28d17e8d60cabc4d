"""Where transport stands: placing stands hold the object over the spot; handle stands line
the arm's shoulder up with the handle."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest

from robocram.plans.fetch import fetch
from robocram.plans.known_robot import KnownRobot
from robocram.plans.stands import STAND_TURNS, handle_stands, placing_stands, yaw_of
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose

SPOT = Pose((-0.3, -1.1, 0.8))  # [m] over the table's north half, in map


@pytest.fixture()
def pr2_kitchen() -> Iterator[KitchenScene]:
    scene = kitchen_scene("pr2")
    yield scene
    scene.world.close()


def test_every_placing_stand_holds_the_object_over_the_spot(pr2_kitchen: KitchenScene) -> None:
    world = pr2_kitchen.world
    with simulated_robot(world, pr2_kitchen.robot):
        fetch("mug")
        stands = list(placing_stands(KnownRobot(pr2_kitchen.robot), "mug-1", SPOT))
        assert len(stands) == STAND_TURNS
        yaws = sorted(round(math.degrees(yaw_of(s))) % 360 for s in stands)
        assert len(set(yaws)) == STAND_TURNS  # each a different turn about the spot
        for stand in stands:
            world.set_pose(pr2_kitchen.robot, stand)  # the held mug rides along
            x, y, _ = world.pose("mug-1").position
            assert (x, y) == pytest.approx(SPOT.position[:2], abs=1e-3)


def test_handle_stands_face_the_handle_with_the_shoulder_in_line(
    pr2_kitchen: KitchenScene,
) -> None:
    world = pr2_kitchen.world
    handle = world.link_pose("kitchen", "drawer_unit_drawer_3_handle")
    with simulated_robot(world, pr2_kitchen.robot):
        stands = list(
            handle_stands(KnownRobot(pr2_kitchen.robot), ["left", "right"], handle, 0.4, True)
        )
    assert [s.arm for s in stands] == ["left"] * 3 + ["right"] * 3
    for stand in stands:
        assert yaw_of(stand.pose) == pytest.approx(math.pi / 2, abs=1e-6)  # facing north
        world.set_pose(pr2_kitchen.robot, stand.pose)
        prefix = stand.arm[0]
        shoulder = world.link_pose(pr2_kitchen.robot, f"{prefix}_shoulder_pan_link").position
        assert shoulder[0] == pytest.approx(handle.position[0], abs=0.01)
    distances = [handle.position[1] - s.pose.position[1] for s in stands[:3]]
    assert distances == pytest.approx([0.9, 1.0, 0.8], abs=1e-6)  # opening + clearances

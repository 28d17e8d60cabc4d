"""A picture's camera frames the robot at its task: checked by projecting the robot's bounds
through a pinhole camera written here, not by the framing code."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.world import World
from robocram.world.view_framing import Follower, Framing, frame_task
from tests.pinhole import box_corners, view_offsets

FOV = math.radians(45.0)


def _offsets(points: np.ndarray, framing: Framing) -> np.ndarray:
    return view_offsets(points, framing.eye, framing.target, FOV)


def _corners(world: World, name: str) -> np.ndarray:
    return box_corners(*world.aabb(name))


@pytest.fixture(scope="module")
def kitchen() -> Iterator[World]:
    scene = kitchen_scene("pr2")
    yield scene.world
    scene.world.close()


def test_the_task_view_holds_the_robot_and_the_items_near_it(kitchen: World) -> None:
    framing = frame_task(kitchen, kitchen.robot("pr2"), FOV)
    for name in ("pr2", "mug-1", "bowl-1"):
        assert np.abs(_offsets(_corners(kitchen, name), framing)).max() <= 1.0, name
    assert framing.target[1] > 0.2  # looked at between the robot and the counter it faces


def test_the_follower_keeps_the_robot_large_and_centred_as_it_drives(kitchen: World) -> None:
    robot = kitchen.robot("pr2")
    start = kitchen.pose("pr2")
    follower = Follower.of(kitchen, robot, FOV)
    sizes = []
    try:
        for place in (start, Pose((0.4, -0.9, 0.0), start.orientation)):
            kitchen.set_pose("pr2", place)
            offsets = _offsets(_corners(kitchen, "pr2"), follower.framing(kitchen, robot))
            assert np.abs(offsets).max() <= 1.0  # all of it in view
            assert abs(offsets[:, 0].mean()) < 0.2  # and in the middle
            sizes.append(offsets[:, 1].max() - offsets[:, 1].min())
    finally:
        kitchen.set_pose("pr2", start)
    assert min(sizes) > 1.2  # more than 60 % of the picture's height: its hands show
    assert sizes[0] == pytest.approx(sizes[1], rel=0.05)  # never zoomed

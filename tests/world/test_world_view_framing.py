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

FOV = math.radians(45.0)


def _offsets(points: np.ndarray, framing: Framing) -> np.ndarray:
    """(right, up) of each point as a share of the half-height of a view FOV high."""
    eye, target = np.asarray(framing.eye), np.asarray(framing.target)
    forward = (target - eye) / np.linalg.norm(target - eye)
    right = np.cross(forward, (0.0, 0.0, 1.0))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    rel = points - eye
    depth = rel @ forward
    assert (depth > 0).all()
    half = math.tan(FOV / 2) * depth
    return np.stack([(rel @ right) / half, (rel @ up) / half], axis=1)


def _corners(world: World, name: str) -> np.ndarray:
    low, high = world.aabb(name)
    return np.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1])
                     for z in (low[2], high[2])])  # fmt: skip


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

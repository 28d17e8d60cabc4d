"""Fixtures shared by the motion tests."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.scenes import kitchen_scene
from robocram.world import World


@pytest.fixture(scope="module")
def kitchen() -> Iterator[World]:
    """The PR2 in robocram's kitchen with both arms parked (a test restores what it moves)."""
    scene = kitchen_scene("pr2")
    world = scene.world
    for arm in world.robot("pr2").description.arms.values():
        world.set_joint_states("pr2", dict(arm.parking))
    yield world
    world.close()

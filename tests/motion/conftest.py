"""Fixtures shared by the motion tests."""

from __future__ import annotations

import importlib.util
import sys
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType

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


@pytest.fixture(scope="session")
def timing_judge() -> ModuleType:
    """``timing_judge.py`` beside this file (tests are not a package: loaded by path)."""
    path = Path(__file__).with_name("timing_judge.py")
    spec = importlib.util.spec_from_file_location("motion_timing_judge", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up there
    spec.loader.exec_module(module)
    return module

"""A traced pick-up with a failing first branch, and a traced run of trajectories, shared by
the trace and export tests (the audit tests' traced kitchen transports are every module's:
``tests/kitchen_transports.py``)."""

from __future__ import annotations

import importlib.util
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from robocram.designators import a
from robocram.execution import TaskSnapshot, perform, try_in_order
from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.traces import StoredWorldState, trace_to
from robocram.world import World

TORSO_TOO_HIGH = 5.0  # [m] far above the PR2's torso limit: the first branch fails


@dataclass
class TracedPickUp:
    """The database, the live tree and world at the end of a traced PR2 pick-up."""

    db_path: Path
    tree: TaskSnapshot
    world: World
    final: StoredWorldState
    run: int


def traced_pick_up(db_path: Path) -> TracedPickUp:
    """Trace ``try_in_order(raise torso too high, pick up)`` on the PR2 into ``db_path``."""
    scene = tabletop_scene("pr2")
    with (
        trace_to(db_path, world=scene.world) as tracer,
        simulated_robot(scene.world, "pr2", name="pick-mug") as run,
    ):
        try_in_order(
            ("too-high", lambda: perform(a.motion(type="moving-torso", joint_angle=5.0))),
            ("pick", lambda: pick_up(scene.look_target)),
        )
    final = StoredWorldState.capture(scene.world, 0.0)
    return TracedPickUp(db_path, run.tree.snapshot(), scene.world, final, tracer.runs[0])


@pytest.fixture(scope="module")
def pick_up_trace(tmp_path_factory: pytest.TempPathFactory) -> Iterator[TracedPickUp]:
    traced = traced_pick_up(tmp_path_factory.mktemp("traces") / "runs.db")
    yield traced
    traced.world.close()


def _trajectory_run_module() -> ModuleType:
    """``trajectory_run.py`` beside this file (tests are not a package: loaded by path)."""
    path = Path(__file__).with_name("trajectory_run.py")
    spec = importlib.util.spec_from_file_location("traces_trajectory_run", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up while being made
    spec.loader.exec_module(module)
    return module


trajectory_run_module = _trajectory_run_module()


@pytest.fixture(scope="module")
def trajectory_run(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Any]:
    traced = trajectory_run_module.traced_trajectory_run(
        tmp_path_factory.mktemp("trajectories") / "runs.db"
    )
    yield traced
    traced.world.close()

"""A traced pick-up with a failing first branch, shared by the trace and export tests."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

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

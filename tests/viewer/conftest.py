"""A PR2 pick-up (first branch failing, after asking a costmap where to stand) shown live
in a viewer and traced to a database: run once for the viewer tests (one worker runs them,
the ``viewer`` group); a test that changes the viewer (its caption, camera, overlay) puts
it back. Its pages are lit without the environment map: software WebGL took ~8 s of CPU to
build it on each page load, and no test here is about the lighting."""

from __future__ import annotations

import socket
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

from robocram.designators import a
from robocram.execution import TaskSnapshot, listening, perform, try_in_order
from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.traces import trace_to
from robocram.viewer import LiveFeed, Viewer
from robocram.world import World


def free_port() -> int:
    """A port nothing listens on now (the OS picks it)."""
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


@dataclass
class LiveRun:
    """The viewer after the run, the live world and tree, and the trace database."""

    viewer: Viewer
    world: World
    tree: TaskSnapshot
    db_path: Path
    run: int


@pytest.fixture(scope="session")
def live_run(tmp_path_factory: pytest.TempPathFactory) -> Iterator[LiveRun]:
    db_path = tmp_path_factory.mktemp("viewer") / "runs.db"
    scene = tabletop_scene("pr2")
    viewer = Viewer(scene.world, port=free_port(), environment_map=False)
    with (
        trace_to(db_path, world=scene.world) as tracer,
        LiveFeed(viewer, scene.world) as feed,
        listening(feed),
        simulated_robot(scene.world, "pr2", name="pick-mug") as run,
    ):
        a.location(reachable_for="pr2", object="mug-1").reference()  # through a costmap
        try_in_order(
            ("too-high", lambda: perform(a.motion(type="moving-torso", joint_angle=5.0))),
            ("pick", lambda: pick_up(scene.look_target)),
        )
    yield LiveRun(viewer, scene.world, run.tree.snapshot(), db_path, tracer.runs[0])
    viewer.close()
    scene.world.close()

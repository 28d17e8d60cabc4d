"""A location resolved through a costmap inside a traced run keeps that costmap."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from robocram.costmaps import Costmap, observing_costmaps
from robocram.designators import a
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.traces import TraceDatabase, run_costmaps, trace_to


def test_the_costmap_behind_a_resolved_location_is_stored_with_its_task(tmp_path: Path) -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    seen: list[tuple[object, Costmap]] = []
    designator = a.location(reachable_for="pr2", object="mug-1")
    with (
        trace_to(tmp_path / "costmaps.db", world=world) as tracer,
        observing_costmaps(lambda d, c: seen.append((d, c))),
        simulated_robot(world, "pr2", name="where-to-stand"),
    ):
        standing = designator.reference()
    world.close()
    ((observed_for, observed),) = seen
    assert observed_for is designator
    with TraceDatabase(tmp_path / "costmaps.db", create=False) as db:
        (stored,) = run_costmaps(db, tracer.runs[0])
    assert stored.task_path == "where-to-stand"
    assert stored.designator == designator.description
    assert stored.origin == observed.grid.origin
    assert stored.resolution == observed.grid.resolution
    assert np.array_equal(stored.weights, observed.weights)  # bit-identical
    assert np.array_equal(stored.heights, observed.heights)
    assert stored.weights.sum() == np.float64(observed.weights.sum())
    points, weights = stored.cells()
    assert len(points) == np.count_nonzero(observed.weights) and np.all(weights > 0)
    nearest = np.min(
        np.hypot(points[:, 0] - standing.position[0], points[:, 1] - standing.position[1])
    )
    assert nearest <= stored.resolution / np.sqrt(2) + 1e-9  # the pose lies in a live cell

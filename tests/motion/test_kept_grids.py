"""A window of the world's kept furniture grid marks every cell the grid built for that
window alone marks (more only at its very border, never looked up from inside), and it
follows the furniture when that moves."""

from __future__ import annotations

import math

import numpy as np

from robocram.motion.height_bins import HeightBins
from robocram.motion.kept_grids import kept_grids
from robocram.motion.obstacle_grid import ObstacleGrid
from robocram.scenes import kitchen_scene
from robocram.world import ObstacleBoxes

CELL = 0.01


def _alone(obstacles: ObstacleBoxes, lower: tuple[float, float], upper: tuple[float, float],
           bins: HeightBins) -> ObstacleGrid:  # fmt: skip
    reaching = np.flatnonzero(
        (obstacles.low[:, 0] <= upper[0]) & (obstacles.high[:, 0] >= lower[0])
        & (obstacles.low[:, 1] <= upper[1]) & (obstacles.high[:, 1] >= lower[1])
    )  # fmt: skip
    table = np.stack([obstacles.low[reaching], obstacles.high[reaching]], axis=1)
    return ObstacleGrid.build(table, lower, upper, CELL, 0.014, bins)


def test_windows_of_the_kept_grid_match_grids_built_alone() -> None:
    world = kitchen_scene("pr2").world
    kept = world.derived(kept_grids)
    bins = HeightBins.up_to(1.5)
    rng = np.random.default_rng(5)
    for trial in range(12):
        if trial == 6:  # the furniture moves: a drawer opens
            world.set_joint_states("kitchen", {"drawer_unit_drawer_1_joint": 0.3})
        obstacles = world.obstacle_boxes(["pr2", "floor"])
        x, y = rng.uniform(-3.0, 2.0, 2)
        lower = (math.floor(x / CELL) * CELL, math.floor(y / CELL) * CELL)
        upper = (x + rng.uniform(0.5, 2.0), y + rng.uniform(0.5, 2.0))
        window = kept.window(obstacles, lower, upper, CELL, 0.014, bins)
        alone = _alone(obstacles, lower, upper, bins)
        assert window.origin == alone.origin and window.masks.shape == alone.masks.shape
        assert not (alone.masks & ~window.masks).any()  # nothing missing
        inner = (slice(2, -2), slice(2, -2))
        assert np.array_equal(window.masks[inner], alone.masks[inner])

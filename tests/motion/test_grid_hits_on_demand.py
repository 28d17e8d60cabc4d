"""The fast check looked up on demand gives the whole run's answers, in any order of
asking, and looks up only the poses near those asked."""

from __future__ import annotations

import math

import numpy as np
import pytest

from robocram.motion import grid_hits_on_demand
from robocram.motion.grid_hits_on_demand import LOOKUP_ROWS, GridHitsOnDemand
from robocram.motion.height_bins import HeightBins
from robocram.motion.obstacle_grid import ObstacleGrid

CELL = 0.01  # [m]


def _scene(seed: int, points: int) -> tuple[ObstacleGrid, np.ndarray, np.ndarray, np.ndarray]:
    """A grid of random boxes, robot sample points (base frame) with height masks, and
    poses along a wavy drive through the boxes."""
    rng = np.random.default_rng(seed)
    bins = HeightBins.up_to(1.5)
    lows = np.column_stack(
        [rng.uniform(0.5, 4.5, 14), rng.uniform(0.5, 4.5, 14), rng.uniform(0, 1, 14)]
    )
    highs = lows + np.column_stack([rng.uniform(0.05, 0.3, (14, 2)), rng.uniform(0.05, 0.5, 14)])
    boxes = np.stack([lows, highs], axis=1)
    grid = ObstacleGrid.build(boxes, (0.0, 0.0), (5.0, 5.0), CELL, 0.0, bins)
    xy = rng.uniform(-0.3, 0.3, (points, 2))
    heights = rng.uniform(0.0, 1.4, points)
    masks = np.array(bins.masks(heights, heights + 0.1), dtype=np.int64)
    t = np.linspace(0.0, 1.0, 300)
    poses = np.column_stack([1.0 + 3.0 * t, 2.5 + 1.2 * np.sin(7.0 * t), 4.0 * np.cos(3.0 * t)])
    return grid, xy, masks, poses


def _plain_hit(
    grid: ObstacleGrid, pose: np.ndarray, xy: np.ndarray, masks: np.ndarray
) -> bool | None:
    """The pose's answer recomputed point by point in plain floats; None when a point lies
    within a millionth of a cell of a cell's edge (rounding could decide there)."""
    c, s = math.cos(pose[2]), math.sin(pose[2])
    hit = False
    for (px, py), bits in zip(xy.tolist(), masks.tolist(), strict=True):
        u = (pose[0] + c * px - s * py - grid.origin[0]) / CELL
        v = (pose[1] + s * px + c * py - grid.origin[1]) / CELL
        if min(u - math.floor(u), math.ceil(u) - u, v - math.floor(v), math.ceil(v) - v) < 1e-6:
            return None
        hit = hit or bool(int(grid.masks[int(u), int(v)]) & bits)
    return hit


@pytest.mark.parametrize("points", [300, 700])  # one block of a 128-pose chunk; several
def test_answers_equal_the_whole_runs_in_any_order(points: int) -> None:
    grid, xy, masks, poses = _scene(3, points)
    whole = grid.hits(poses, xy, masks, inside=True)
    assert 0.2 < whole.mean() < 0.8  # both answers occur
    order = np.random.default_rng(5).permutation(len(poses))
    lazy = GridHitsOnDemand(grid, poses, xy, masks, inside=True)
    asked = np.array([lazy[int(k)] for k in order])
    assert np.array_equal(asked, whole[order])  # bit for bit: the same cells
    plain = [_plain_hit(grid, pose, xy, masks) for pose in poses[:60]]
    decided = [(k, hit) for k, hit in enumerate(plain) if hit is not None]
    assert len(decided) > 20
    assert all(bool(whole[k]) == hit for k, hit in decided)


def test_the_clipped_lookup_answers_at_once() -> None:
    grid, xy, masks, poses = _scene(4, 200)
    lazy = GridHitsOnDemand(grid, poses, xy, masks, inside=False)
    expected = grid.hits(poses, xy, masks, inside=False)
    assert [lazy[k] for k in range(len(poses))] == expected.tolist()


def test_only_the_rows_round_those_asked_are_looked_up(monkeypatch: pytest.MonkeyPatch) -> None:
    grid, xy, masks, poses = _scene(6, 300)
    looked: list[tuple[int, int]] = []
    real = ObstacleGrid.hits_of_units

    def counted(self: ObstacleGrid, units: np.ndarray, rows: np.ndarray, m: np.ndarray,
                first: int, stop: int) -> np.ndarray:  # fmt: skip
        looked.append((first, stop))
        return real(self, units, rows, m, first, stop)

    monkeypatch.setattr(grid_hits_on_demand.ObstacleGrid, "hits_of_units", counted)
    chunk = poses[:128]
    lazy = GridHitsOnDemand(grid, chunk, xy, masks, inside=True)
    block = grid.block(xy)
    assert block < 128  # the chunk spans several products
    _ = lazy[0], lazy[1], lazy[LOOKUP_ROWS - 1]
    assert looked == [(0, LOOKUP_ROWS)]
    _ = lazy[block]  # the next product's first pose
    assert looked[-1] == (0, min(LOOKUP_ROWS, 128 - block))
    assert sum(stop - first for first, stop in looked) < 128

"""The obstacle grid marks exactly the cells a box (grown) reaches, at the heights it spans."""

from __future__ import annotations

import math

import numpy as np

from robocram.motion.height_bins import HeightBins
from robocram.motion.obstacle_grid import Box, ObstacleGrid


def _by_hand(boxes: list[Box], lower: tuple[float, float], shape: tuple[int, int],
             cell: float, dilation: float, bins: HeightBins) -> np.ndarray:  # fmt: skip
    masks = np.zeros(shape, dtype=np.int64)
    for low, high in boxes:
        i0, i1 = (min(max(math.floor((v - lower[0]) / cell), 0), shape[0] - 1)
                  for v in (low[0] - dilation, high[0] + dilation))  # fmt: skip
        j0, j1 = (min(max(math.floor((v - lower[1]) / cell), 0), shape[1] - 1)
                  for v in (low[1] - dilation, high[1] + dilation))  # fmt: skip
        masks[i0 : i1 + 1, j0 : j1 + 1] |= bins.mask(low[2], high[2])
    return masks


def test_boxes_are_rasterised_cell_by_cell() -> None:
    rng = np.random.default_rng(3)
    bins = HeightBins.up_to(1.4)
    for _ in range(20):
        low = rng.uniform(-3.0, 3.0, (25, 3))
        low[:, 2] = rng.uniform(-0.2, 1.6, 25)  # some above every bin
        high = low + rng.uniform(0.0, 1.5, (25, 3))
        boxes: list[Box] = [
            ((*map(float, a),), (*map(float, b),)) for a, b in zip(low, high, strict=True)
        ]  # type: ignore[misc]
        lower, upper = (-1.234, -0.5), (1.0, 2.345)
        grid = ObstacleGrid.build(boxes, lower, upper, 0.01, 0.014, bins)
        expected = _by_hand(boxes, lower, grid.masks.shape, 0.01, 0.014, bins)
        assert np.array_equal(grid.masks, expected)
        table = ObstacleGrid.build(np.stack([low, high], axis=1), lower, upper, 0.01, 0.014, bins)
        assert np.array_equal(table.masks, expected)
    assert not ObstacleGrid.build([], (0.0, 0.0), (1.0, 1.0), 0.01, 0.0, bins).masks.any()

"""The footprint's squares, the boundary and the grown squares are what the module says."""

from __future__ import annotations

import numpy as np

from robocram.motion.height_bins import HeightBins
from robocram.motion.obstacle_grid import Box
from robocram.motion.robot_footprint import RobotFootprint


def _boxes(rng: np.random.Generator) -> list[Box]:
    found: list[Box] = []
    for _ in range(12):
        low = rng.uniform(-0.4, 0.3, 3)
        high = low + rng.uniform(0.01, 0.3, 3)
        found.append((tuple(low), tuple(high)))  # type: ignore[arg-type]
    return found


def test_the_grown_squares_hold_every_square_within_reach_with_its_bits() -> None:
    """Each square of the footprint, shifted by up to ``grown_by`` along both axes, lies
    on grown squares carrying its bits: what the proof of a block of poses relies on."""
    rng = np.random.default_rng(5)
    bins = HeightBins.up_to(1.0)
    for _ in range(5):
        fp = RobotFootprint.build(_boxes(rng), 0.05, bins, 0.02, 0.002)
        grown = {
            tuple(np.round(p / fp.spacing - 0.5).astype(int)): int(m)
            for p, m in zip(fp.grown_points, fp.grown_masks, strict=True)
        }
        reach = round(fp.grown_by / fp.spacing)
        for point, mask in zip(fp.points, fp.masks, strict=True):
            i, j = np.round(point / fp.spacing - 0.5).astype(int)
            for di in range(-reach, reach + 1):
                for dj in range(-reach, reach + 1):
                    assert grown[(i + di, j + dj)] & int(mask) == int(mask)
        assert len(fp.grown_points) > len(fp.points)


def test_height_masks_of_many_equal_one_by_one() -> None:
    bins = HeightBins.up_to(1.3)
    rng = np.random.default_rng(2)
    low = rng.uniform(-0.3, 1.6, 200)
    high = low + rng.uniform(0.0, 0.8, 200)
    many = bins.masks(low, high)
    assert many == [int(bins.mask(float(a), float(b))) for a, b in zip(low, high, strict=True)]


def test_every_grown_square_lies_within_the_grown_reach() -> None:
    rng = np.random.default_rng(7)
    bins = HeightBins.up_to(1.0)
    fp = RobotFootprint.build(_boxes(rng), 0.05, bins, 0.02, 0.002)
    corners = np.abs(fp.grown_points) + fp.spacing / 2.0
    assert np.linalg.norm(corners, axis=1).max() <= fp.grown_reach + 1e-12
    assert fp.grown_reach > fp.reach

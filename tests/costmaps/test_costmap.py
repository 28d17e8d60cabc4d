"""The costmap value: grid geometry, product and normalisation, seeded lazy sampling."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from robocram.costmaps import Costmap, CostmapError, CostmapGrid, CostmapInputError, gaussian, ring


def test_grid_centres_and_cells_agree() -> None:
    grid = CostmapGrid.around((1.0, -2.0), 2.0, 0.1)
    x, y = grid.centres()
    assert grid.shape == (20, 20)
    assert x.mean() == pytest.approx(1.0) and y.mean() == pytest.approx(-2.0)
    assert grid.cell_of(float(x[3, 7]), float(y[3, 7])) == (3, 7)
    assert grid.cell_of(100.0, 0.0) is None


@pytest.mark.parametrize("resolution", [0.0, -0.05])
def test_resolution_must_be_positive(resolution: float) -> None:
    with pytest.raises(CostmapInputError, match="resolution") as err:
        CostmapGrid.around((0.0, 0.0), 2.0, resolution)
    assert err.value.culprit == resolution
    assert isinstance(err.value, CostmapError)


def test_product_is_normalised_and_zero_rules_out() -> None:
    grid = CostmapGrid.around((0.0, 0.0), 2.0, 0.1)
    near = gaussian(grid, (0.5, 0.0), ((0.1, 0.0), (0.0, 0.1)))
    band = ring(grid, (0.0, 0.0), 0.3, 0.8)
    costmap = Costmap.from_layers(grid, [near, band])
    assert costmap.weights.sum() == pytest.approx(1.0)
    x, y = grid.centres()
    distance = np.hypot(x, y)
    assert np.all(costmap.weights[(distance < 0.3) | (distance > 0.8)] == 0)
    best = next(costmap.best_first())
    bx, by, _ = costmap.position(best)
    assert (bx, by) == pytest.approx((0.5, 0.0), abs=0.06)


def test_weighted_sampling_is_seeded_without_replacement() -> None:
    grid = CostmapGrid.around((0.0, 0.0), 1.0, 0.1)
    costmap = Costmap.from_layers(grid, [gaussian(grid, (0.0, 0.0), ((0.05, 0), (0, 0.05)))])
    first = list(costmap.weighted_random(np.random.default_rng(7)))
    again = list(costmap.weighted_random(np.random.default_rng(7)))
    other = list(costmap.weighted_random(np.random.default_rng(8)))
    assert first == again and first != other
    assert len(first) == len(set(first)) == 100
    # heavier cells come early: the first 10 draws average far more weight than the rest
    weights = [costmap.weights[c] for c in first]
    assert np.mean(weights[:10]) > 2 * np.mean(weights[50:])


def test_bad_layers_are_refused() -> None:
    grid = CostmapGrid.around((0.0, 0.0), 1.0, 0.1)
    with pytest.raises(CostmapInputError, match="does not fit"):
        Costmap.from_layers(grid, [np.ones((3, 3))])
    with pytest.raises(CostmapInputError, match=">= 0"):
        Costmap.from_layers(grid, [-np.ones(grid.shape)])


def test_empty_costmap_yields_nothing() -> None:
    grid = CostmapGrid.around((0.0, 0.0), 1.0, 0.1)
    costmap = Costmap.from_layers(grid, [np.zeros(grid.shape)])
    assert costmap.empty
    assert list(itertools.islice(costmap.best_first(), 3)) == []

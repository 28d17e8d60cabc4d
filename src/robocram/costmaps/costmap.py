"""A costmap: a normalised product of cost layers on a grid in the map frame.

As in CRAM, each cost function gives every cell a non-negative weight; the costmap is
their product, normalised to sum 1, so a cell any function rules out (weight 0) is never
proposed. Heights (the z of a 3-D pose, e.g. a table top) travel with the layers.
Sampling is lazy: best-first, or weighted random without replacement from a seeded
generator (Efraimidis-Spirakis keys), so the same seed gives the same cells.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.grid import CostmapGrid, FloatGrid
from robocram.costmaps.picture import draw_costmap

if TYPE_CHECKING:
    from pathlib import Path

    from robocram.world import World


@dataclass(frozen=True, eq=False)
class Costmap:
    """Normalised weights (sum 1, or all 0 when nothing fits) and cell heights [m]."""

    grid: CostmapGrid
    weights: FloatGrid
    heights: FloatGrid

    @classmethod
    def from_layers(
        cls, grid: CostmapGrid, layers: list[FloatGrid], heights: FloatGrid | None = None
    ) -> Costmap:
        """The normalised product of ``layers`` (each of ``grid.shape``, values >= 0)."""
        product = np.ones(grid.shape)
        for layer in layers:
            if layer.shape != grid.shape:
                raise CostmapInputError(
                    f"cost layer of shape {layer.shape} does not fit the grid {grid.shape}",
                    layer.shape,
                )
            if np.any(layer < 0) or not np.all(np.isfinite(layer)):
                raise CostmapInputError("cost layers must be finite and >= 0", layer)
            product = product * layer
        total = float(product.sum())
        weights = product / total if total > 0 else product
        z = np.zeros(grid.shape) if heights is None else heights
        return cls(grid, weights, z)

    @property
    def empty(self) -> bool:
        """Whether no cell has any weight."""
        return not bool(np.any(self.weights > 0))

    def best_first(self) -> Iterator[tuple[int, int]]:
        """Cells ``(row, column)`` of positive weight, highest first (ties by index)."""
        flat = self.weights.ravel()
        order = np.argsort(-flat, kind="stable")
        for index in order[: int(np.count_nonzero(flat > 0))]:
            yield divmod(int(index), self.grid.shape[1])

    def weighted_random(self, rng: np.random.Generator) -> Iterator[tuple[int, int]]:
        """Cells of positive weight drawn by weight without replacement, seeded by ``rng``."""
        flat = self.weights.ravel()
        alive = np.flatnonzero(flat > 0)
        keys = -np.log(rng.random(len(alive))) / flat[alive]  # smallest key drawn first
        for index in alive[np.argsort(keys, kind="stable")]:
            yield divmod(int(index), self.grid.shape[1])

    def position(
        self, cell: tuple[int, int], rng: np.random.Generator | None = None
    ) -> tuple[float, float, float]:
        """Map (x, y, z) [m] of ``cell``: its centre, or a seeded point inside it."""
        row, col = cell
        x = self.grid.origin[0] + col * self.grid.resolution
        y = self.grid.origin[1] + row * self.grid.resolution
        if rng is not None:
            dx, dy = (rng.random(2) - 0.5) * self.grid.resolution
            x, y = x + float(dx), y + float(dy)
        return x, y, float(self.heights[row, col])

    def to_png(
        self,
        path: str | Path,
        world: World | None = None,
        marks: int = 10,
        pixels_per_cell: int = 4,
    ) -> Path:
        """Draw the weights over a top-down render of ``world``; mark the ``marks`` best cells."""
        best = list(itertools.islice(self.best_first(), marks))
        return draw_costmap(self.grid, self.weights, best, path, world, pixels_per_cell)

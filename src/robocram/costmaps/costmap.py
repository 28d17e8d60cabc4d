"""A costmap: a normalised product of cost layers on a grid in the map frame.

As in CRAM, each cost function gives every cell a non-negative weight; the costmap is
their product, normalised to sum 1, so a cell any function rules out (weight 0) is never
proposed. Heights (the z of a 3-D pose, e.g. a table top) travel with the layers.
Sampling is lazy: best-first, or weighted random without replacement from a seeded
generator (Efraimidis-Spirakis keys), so the same seed gives the same cells.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.costmaps.errors import CostmapInputError

if TYPE_CHECKING:
    from pathlib import Path

    from robocram.world import World

FloatGrid = NDArray[np.float64]
BoolGrid = NDArray[np.bool_]


@dataclass(frozen=True)
class CostmapGrid:
    """Where the cells are: ``origin`` is the map (x, y) [m] of cell (0, 0)'s centre.

    Arrays over the grid are indexed ``[row, column]`` = ``[y index, x index]``.
    """

    origin: tuple[float, float]  # [m]
    resolution: float  # [m] cell side
    shape: tuple[int, int]  # (rows along y, columns along x)

    def __post_init__(self) -> None:
        if not (isinstance(self.resolution, int | float) and self.resolution > 0):
            raise CostmapInputError(
                f"costmap resolution must be a number > 0 [m], got {self.resolution!r}; try 0.05",
                self.resolution,
            )
        if min(self.shape) < 1:
            raise CostmapInputError(f"costmap shape {self.shape} has no cells", self.shape)

    @classmethod
    def around(cls, centre: tuple[float, float], size: float, resolution: float) -> CostmapGrid:
        """A square grid of side ``size`` [m] centred on ``centre`` (map x, y)."""
        if not (isinstance(resolution, int | float) and resolution > 0):
            raise CostmapInputError(
                f"costmap resolution must be a number > 0 [m], got {resolution!r}; try 0.05",
                resolution,
            )
        if not size > 0:
            raise CostmapInputError(f"costmap size must be > 0 [m], got {size!r}", size)
        cells = max(1, math.ceil(size / resolution))
        half = (cells - 1) * resolution / 2
        return cls((centre[0] - half, centre[1] - half), float(resolution), (cells, cells))

    def centres(self) -> tuple[FloatGrid, FloatGrid]:
        """Map x and y [m] of every cell centre, each an array of :attr:`shape`."""
        rows, cols = self.shape
        xs = self.origin[0] + self.resolution * np.arange(cols)
        ys = self.origin[1] + self.resolution * np.arange(rows)
        x, y = np.meshgrid(xs, ys)
        return x, y

    def cell_of(self, x: float, y: float) -> tuple[int, int] | None:
        """``(row, column)`` of the cell holding map point (x, y), or None outside."""
        col = round((x - self.origin[0]) / self.resolution)
        row = round((y - self.origin[1]) / self.resolution)
        if 0 <= row < self.shape[0] and 0 <= col < self.shape[1]:
            return row, col
        return None

    def extent(self) -> tuple[float, float, float, float]:
        """``(x_min, x_max, y_min, y_max)`` [m] of the grid's outer edges."""
        half = self.resolution / 2
        rows, cols = self.shape
        x0, y0 = self.origin
        return (
            x0 - half,
            x0 + (cols - 1) * self.resolution + half,
            y0 - half,
            y0 + (rows - 1) * self.resolution + half,
        )


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
        from robocram.costmaps.picture import draw_costmap

        return draw_costmap(self, path, world, marks, pixels_per_cell)

"""The grid of a costmap: cell centres in the map frame, indexed ``[row, column]``."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from robocram.costmaps.errors import CostmapInputError

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


def erode(mask: BoolGrid, radius_cells: float, outside: bool = False) -> BoolGrid:
    """Cells of ``mask`` with every cell within ``radius_cells`` also in ``mask``.

    ``outside`` is what cells beyond the grid count as.
    """
    reach = math.floor(radius_cells)
    out = mask.copy()
    rows, cols = mask.shape
    padded = np.full((rows + 2 * reach, cols + 2 * reach), outside, dtype=bool)
    padded[reach : reach + rows, reach : reach + cols] = mask
    for dr in range(-reach, reach + 1):
        for dc in range(-reach, reach + 1):
            if dr * dr + dc * dc <= radius_cells * radius_cells:
                out &= padded[reach + dr : reach + dr + rows, reach + dc : reach + dc + cols]
    return out


def dilate(mask: BoolGrid, radius_cells: float) -> BoolGrid:
    """Cells within ``radius_cells`` of a cell of ``mask``."""
    return ~erode(~mask, radius_cells, outside=True)

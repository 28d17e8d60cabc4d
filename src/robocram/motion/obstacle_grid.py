"""The world's obstacles seen from above: a grid of cells, each with its occupied heights.

Every link of every obstacle is a world-aligned box (its AABB, conservative); a cell holds
the height bits (:class:`~robocram.motion.height_bins.HeightBins`) of all boxes over it.
The boxes are grown by ``dilation`` first, so that looking up one point per robot sample
square (:mod:`robocram.motion.robot_footprint`) is still conservative: a square that
touches a box has its centre inside the grown box, hence in a marked cell.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from robocram.motion.height_bins import HeightBins

Box = tuple[tuple[float, float, float], tuple[float, float, float]]  # (lower, upper) [m]
IntArray = npt.NDArray[np.int64]
LOOKUPS_PER_BLOCK = 16_000  # cells looked up at once: the temporaries stay in the cache


@dataclass(frozen=True)
class ObstacleGrid:
    """Height masks per cell of ``cell`` [m], cell (0, 0) starting at ``origin`` (map)."""

    origin: tuple[float, float]  # [m] map x, y of the grid's corner
    cell: float  # [m]
    masks: IntArray  # shape (nx, ny)

    @classmethod
    def build(
        cls,
        boxes: Sequence[Box] | npt.NDArray[np.float64],
        lower: tuple[float, float],
        upper: tuple[float, float],
        cell: float,
        dilation: float,
        bins: HeightBins,
    ) -> ObstacleGrid:
        """Rasterise ``boxes`` (or their (n, 2, 3) table) grown by ``dilation`` [m] over the
        area ``lower``..``upper``."""
        shape = (
            int(math.ceil((upper[0] - lower[0]) / cell)) + 1,
            int(math.ceil((upper[1] - lower[1]) / cell)) + 1,
        )
        masks = np.zeros(shape, dtype=np.int64)
        table = np.asarray(boxes, dtype=float).reshape(-1, 2, 3)
        first = cls._indices(table[:, 0, :2] - dilation, lower, cell, shape)
        last = cls._indices(table[:, 1, :2] + dilation, lower, cell, shape)
        every_bits = bins.masks(table[:, 0, 2], table[:, 1, 2])
        for bits, (i0, j0), (i1, j1) in zip(every_bits, first, last, strict=True):
            if bits:
                masks[i0 : i1 + 1, j0 : j1 + 1] |= bits
        return cls(lower, cell, masks)

    @staticmethod
    def _indices(
        xy: npt.NDArray[np.float64], lower: tuple[float, float], cell: float,
        shape: tuple[int, int],
    ) -> list[list[int]]:  # fmt: skip
        """:meth:`_index` of every row of ``xy`` (n, 2) [m]."""
        i = np.clip(np.floor((xy[:, 0] - lower[0]) / cell), 0, shape[0] - 1)
        j = np.clip(np.floor((xy[:, 1] - lower[1]) / cell), 0, shape[1] - 1)
        found: list[list[int]] = np.stack([i, j], axis=1).astype(np.intp).tolist()
        return found

    def hits(
        self,
        poses: npt.NDArray[np.float64],
        points: npt.NDArray[np.float64],
        masks: IntArray,
        inside: bool,
    ) -> npt.NDArray[np.bool_]:
        """Per base pose ``(x, y, yaw)`` (map), whether any of the robot's sample
        ``points`` (base frame, (n, 2) [m]) lies in a cell sharing bits with its ``masks``.

        ``inside``: the caller knows every point falls on the grid, so the cells are found
        without clipping, in cell units from the start (twice as fast along a motion).
        """
        if not inside:
            cos, sin = np.cos(poses[:, 2:3]), np.sin(poses[:, 2:3])
            x = poses[:, 0:1] + cos * points[:, 0] - sin * points[:, 1]
            y = poses[:, 1:2] + sin * points[:, 0] + cos * points[:, 1]
            cells = np.take(self.masks.ravel(), self.flat_indices(x, y))
            return np.asarray(np.any(cells & masks, axis=1))
        block = self.block(points)
        if len(poses) <= block:
            return self._hits_on_grid(poses, points, masks)
        return np.concatenate([
            self._hits_on_grid(poses[k : k + block], points, masks)
            for k in range(0, len(poses), block)
        ])  # fmt: skip

    def _hits_on_grid(
        self, poses: npt.NDArray[np.float64], points: npt.NDArray[np.float64], masks: IntArray
    ) -> npt.NDArray[np.bool_]:
        """:meth:`hits` of points known to fall on the grid: the cells' rows and columns
        come from one product of the poses' rotations (in cell units) with the points."""
        return self.hits_of_units(self.units(poses, points), poses, masks, 0, len(poses))

    def units(
        self, poses: npt.NDArray[np.float64], points: npt.NDArray[np.float64]
    ) -> npt.NDArray[np.float64]:
        """The rotated ``points`` of every pose in cell units, before the poses' offsets:
        rows the x of every pose, then the y of every pose. One product for all the poses:
        BLAS's rows differ in their last bits with how many poses it is given, so callers
        keep :meth:`hits`' blocks."""
        per_cell = 1.0 / self.cell
        count = len(poses)
        cos, sin = np.cos(poses[:, 2]) * per_cell, np.sin(poses[:, 2]) * per_cell
        rotations = np.empty((2 * count, 2))
        rotations[:count, 0], rotations[:count, 1] = cos, -sin
        rotations[count:, 0], rotations[count:, 1] = sin, cos
        return np.asarray(rotations @ points.T)

    def hits_of_units(
        self,
        units: npt.NDArray[np.float64],
        poses: npt.NDArray[np.float64],
        masks: IntArray,
        first: int,
        stop: int,
    ) -> npt.NDArray[np.bool_]:
        """:meth:`hits` of ``poses[first:stop]`` from their :meth:`units` (of all ``poses``):
        each pose's answer is its row's alone, whichever rows are asked together."""
        per_cell = 1.0 / self.cell
        count = len(poses)
        rows = poses[first:stop]
        i = units[first:stop] + ((rows[:, 0] - self.origin[0]) * per_cell)[:, None]
        j = (
            units[count + first : count + stop]
            + ((rows[:, 1] - self.origin[1]) * per_cell)[:, None]
        )
        flat = i.astype(np.intp)
        flat *= self.masks.shape[1]
        flat += j.astype(np.intp)
        found = np.take(self.masks.ravel(), flat, mode="clip")
        found &= masks
        return np.asarray(found.any(axis=1))

    def block(self, points: npt.NDArray[np.float64]) -> int:
        """How many poses :meth:`hits` looks up at once on the grid with ``points``."""
        return max(1, LOOKUPS_PER_BLOCK // max(len(points), 1))

    def flat_indices(
        self, x: npt.NDArray[np.float64], y: npt.NDArray[np.float64]
    ) -> npt.NDArray[np.intp]:
        """Indices into ``masks.ravel()`` of the cells holding points ``(x, y)`` (map).

        Points off the grid look up its border cells, which hold nothing: every obstacle
        lies well inside the grid.
        """
        nx, ny = self.masks.shape
        i = np.clip(((x - self.origin[0]) / self.cell).astype(np.intp), 0, nx - 1)
        j = np.clip(((y - self.origin[1]) / self.cell).astype(np.intp), 0, ny - 1)
        return i * ny + j

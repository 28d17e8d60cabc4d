"""Obstacle grids of the furniture, kept with the world from drive to drive.

A batch drives the same robot through the same kitchen again and again, and most of what
an obstacle grid rasterises is furniture that never moves (static bodies). Their grid
over the whole world is kept with the world, per height bins and growth; a drive copies
the window it needs and adds the boxes of what may move (a mug on the counter). The
static boxes are compared, not trusted: a kept grid whose furniture moved (a drawer
opened) is built again.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from robocram.motion.height_bins import HeightBins
from robocram.motion.obstacle_grid import ObstacleGrid
from robocram.world import ObstacleBoxes, World

GRIDS_KEPT = 4  # grids a world keeps (postures of different heights, fine and wide)
SLACK = 0.5  # [m] a kept grid reaches this much farther than the first window asked for

Area = tuple[tuple[float, float], tuple[float, float]]  # [m] lower and upper x, y


@dataclass(frozen=True)
class _Furniture:
    """The static rows of a bounds table: what a kept grid was rasterised from."""

    names: tuple[tuple[str, str, int], ...]  # (object, link, index) per row
    low: np.ndarray
    high: np.ndarray

    @classmethod
    def of(cls, obstacles: ObstacleBoxes, static: np.ndarray) -> _Furniture:
        rows = np.flatnonzero(static)
        names = tuple(
            (obstacles.objects[k].name, obstacles.names[k], obstacles.indices[k]) for k in rows
        )
        return cls(names, obstacles.low[rows], obstacles.high[rows])

    def same(self, other: _Furniture) -> bool:
        return (
            self.names == other.names
            and np.array_equal(self.low, other.low)
            and np.array_equal(self.high, other.high)
        )


@dataclass
class KeptGrids:
    """The furniture's grids a world keeps, most recently used last."""

    _grids: dict[tuple[float, float, float], tuple[_Furniture, ObstacleGrid]] = field(
        default_factory=dict
    )
    _source: ObstacleBoxes | None = None  # the table the furniture was last taken from
    _furniture: _Furniture | None = None

    def window(
        self,
        obstacles: ObstacleBoxes,
        lower: tuple[float, float],
        upper: tuple[float, float],
        cell: float,
        dilation: float,
        bins: HeightBins,
    ) -> ObstacleGrid:
        """The grid of ``obstacles`` over ``lower``..``upper`` (``lower`` on the lattice
        of ``cell``), from the kept furniture's grid and the boxes of the bodies that may
        move: every box that, grown, reaches into it is marked as :meth:`ObstacleGrid.build`
        marks it (a box beyond the window marks no border cell it does not reach)."""
        static = np.array([o.is_static for o in obstacles.objects], dtype=bool)
        furniture = self._furniture_of(obstacles, static)
        key = (bins.height, dilation, cell)
        found = self._grids.pop(key, None)
        grid = None
        if found is not None and found[0].same(furniture):
            grid = found[1].window(lower, upper)
        if found is None or grid is None:
            whole = _whole(furniture, lower, upper, cell)
            boxes = np.stack([furniture.low, furniture.high], axis=1)
            found = (furniture, ObstacleGrid.build(boxes, *whole, cell, dilation, bins))
            grid = found[1].window(lower, upper)
        self._grids[key] = found
        while len(self._grids) > GRIDS_KEPT:
            self._grids.pop(next(iter(self._grids)))
        if grid is None:  # beyond even the whole world's grid
            return ObstacleGrid.build(_table(obstacles), lower, upper, cell, dilation, bins)
        start = np.array(lower) - dilation
        end = start + np.array(grid.masks.shape) * cell + 2 * dilation
        reaching = ((obstacles.low[:, :2] <= end) & (obstacles.high[:, :2] >= start)).all(axis=1)
        grid.add(_table(obstacles, np.flatnonzero(reaching & ~static)), dilation, bins)
        return grid

    def _furniture_of(self, obstacles: ObstacleBoxes, static: np.ndarray) -> _Furniture:
        """The static rows of ``obstacles``; the same object for the same table."""
        if obstacles is not self._source or self._furniture is None:
            self._furniture = _Furniture.of(obstacles, static)
            self._source = obstacles
        return self._furniture


def kept_grids(world: World) -> KeptGrids:
    """The grids a world keeps (the key under which :meth:`World.derived` keeps them)."""
    return KeptGrids()


def _table(obstacles: ObstacleBoxes, rows: np.ndarray | None = None) -> np.ndarray:
    """The (n, 2, 3) bounds of ``rows`` (default: all) of ``obstacles``."""
    if rows is None:
        return np.stack([obstacles.low, obstacles.high], axis=1)
    return np.stack([obstacles.low[rows], obstacles.high[rows]], axis=1)


def _whole(
    furniture: _Furniture, lower: tuple[float, float], upper: tuple[float, float], cell: float
) -> Area:
    """The area of a kept grid: the furniture and the window asked for, and some slack;
    its corner on the lattice of ``cell``."""
    low = np.minimum(furniture.low[:, :2].min(axis=0, initial=np.inf), lower) - SLACK
    high = np.maximum(furniture.high[:, :2].max(axis=0, initial=-np.inf), upper) + SLACK
    corner = (math.floor(low[0] / cell) * cell, math.floor(low[1] / cell) * cell)
    return corner, (float(high[0]), float(high[1]))

"""Costmaps as the trace store keeps them: the grid, its weights and heights, and when.

When a location designator is resolved through a costmap inside a traced run, the tracer
(an observer of :func:`~robocram.costmaps.observing_costmaps`) keeps the costmap with the
task that was running, so a viewer can draw it over the world of that moment.
"""

from __future__ import annotations

import zlib
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray
from sqlalchemy import select

from robocram.costmaps import Costmap
from robocram.traces.database import TraceDatabase
from robocram.traces.schema import CostmapRow, TaskRow

FloatArray = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class StoredCostmap:
    """A costmap of a run: built at ``time`` for ``designator`` while ``task_path`` ran."""

    time: float  # [s] since the epoch
    task_path: str | None
    designator: str
    origin: tuple[float, float]  # [m] map (x, y) of cell (0, 0)'s centre
    resolution: float  # [m]
    weights: FloatArray  # [rows, columns], sum 1 (or all 0)
    heights: FloatArray  # [m] map z of each cell

    @classmethod
    def of(
        cls, costmap: Costmap, designator: Any, time: float, task_path: str | None
    ) -> StoredCostmap:
        """Keep ``costmap`` (built for ``designator`` at ``time``) as a trace would."""
        return cls(
            time=time,
            task_path=task_path,
            designator=_description(designator),
            origin=costmap.grid.origin,
            resolution=costmap.grid.resolution,
            weights=costmap.weights.copy(),
            heights=costmap.heights.copy(),
        )

    def cells(self) -> tuple[FloatArray, FloatArray]:
        """Map (x, y, z) [m] of the cells of positive weight, and their weights."""
        rows, cols = np.nonzero(self.weights > 0)
        points = np.stack(
            [
                self.origin[0] + cols * self.resolution,
                self.origin[1] + rows * self.resolution,
                self.heights[rows, cols],
            ],
            axis=1,
        )
        return points, self.weights[rows, cols]


def costmap_row(
    run_id: int, task_id: int | None, time: float, designator: Any, costmap: Costmap
) -> dict[str, Any]:
    """The ``costmaps`` row of ``costmap``, built for ``designator`` at ``time``."""
    grid = costmap.grid
    return {
        "run_id": run_id,
        "task_id": task_id,
        "time": time,
        "designator": _description(designator),
        "origin_x": grid.origin[0],
        "origin_y": grid.origin[1],
        "resolution": grid.resolution,
        "rows": grid.shape[0],
        "columns": grid.shape[1],
        "weights": _pack(costmap.weights),
        "heights": _pack(costmap.heights),
    }


def run_costmaps(db: TraceDatabase, run: int) -> list[StoredCostmap]:
    """The costmaps run ``run`` was resolved through, in the order they were built."""
    query = (
        select(CostmapRow, TaskRow.path)
        .outerjoin(TaskRow, TaskRow.id == CostmapRow.task_id)
        .where(CostmapRow.run_id == run)
        .order_by(CostmapRow.time, CostmapRow.id)
    )
    with db.read() as session:
        return [_stored(row, path) for row, path in session.execute(query)]


def _stored(row: CostmapRow, path: str | None) -> StoredCostmap:
    shape = (row.rows, row.columns)
    return StoredCostmap(
        time=row.time,
        task_path=path,
        designator=row.designator,
        origin=(row.origin_x, row.origin_y),
        resolution=row.resolution,
        weights=_unpack(row.weights, shape),
        heights=_unpack(row.heights, shape),
    )


def _description(designator: Any) -> str:
    return str(getattr(designator, "description", designator))


def _pack(values: FloatArray) -> bytes:
    return zlib.compress(np.ascontiguousarray(values, dtype="<f8").tobytes(), 1)


def _unpack(data: bytes, shape: tuple[int, int]) -> FloatArray:
    return np.frombuffer(zlib.decompress(data), dtype="<f8").reshape(shape).copy()

"""Cost functions of distance alone: a gaussian around a point, a ring, ``near`` and ``at``."""

from __future__ import annotations

import numpy as np

from robocram.costmaps.cost_layer import CostLayer, LocationQuery
from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.grid import BoolGrid, CostmapGrid, FloatGrid

NEAR_DISTANCE = 1.0  # [m] beyond this from the reference object's bounds nothing is "near"
AT_DISTANCE = 0.02  # [m] ``at`` keeps the cells this close to its point (one cell at least)


def gaussian(
    grid: CostmapGrid, mean: tuple[float, float], covariance: tuple[tuple[float, float], ...]
) -> FloatGrid:
    """Unnormalised 2-D gaussian over map (x, y) [m] with a 2 x 2 ``covariance`` [m^2]."""
    cov = np.asarray(covariance, dtype=float)
    if cov.shape != (2, 2) or np.linalg.det(cov) <= 0:
        raise CostmapInputError(
            f"a gaussian needs a positive-definite 2 x 2 covariance, got {covariance!r}",
            covariance,
        )
    x, y = grid.centres()
    d = np.stack([x - mean[0], y - mean[1]], axis=-1)
    mahalanobis = np.einsum("...i,ij,...j->...", d, np.linalg.inv(cov), d)
    return np.asarray(np.exp(-0.5 * mahalanobis), dtype=np.float64)


def ring(
    grid: CostmapGrid, centre: tuple[float, float], min_distance: float, max_distance: float
) -> FloatGrid:
    """1 in cells between ``min_distance`` and ``max_distance`` [m] of ``centre``, else 0."""
    if not 0 <= min_distance < max_distance:
        raise CostmapInputError(
            f"a range needs 0 <= min ({min_distance}) < max ({max_distance}) [m]",
            (min_distance, max_distance),
        )
    x, y = grid.centres()
    d = np.hypot(x - centre[0], y - centre[1])
    return ((d >= min_distance) & (d <= max_distance)).astype(float)


def near_cost(query: LocationQuery, value: object, alive: BoolGrid) -> CostLayer:
    """``near=obj`` (or ``(obj, link)``, a part such as a drawer): weight falls off linearly
    from its bounds to 1 m away."""
    low, high = query.bounds(value, "near")
    x, y = query.centres()
    dx = np.maximum(np.maximum(low[0] - x, x - high[0]), 0.0)
    dy = np.maximum(np.maximum(low[1] - y, y - high[1]), 0.0)
    gap = np.hypot(dx, dy)
    return CostLayer(np.clip(1.0 - gap / NEAR_DISTANCE, 0.0, 1.0))


def at_cost(query: LocationQuery, value: object, alive: BoolGrid) -> CostLayer:
    """``at=point`` (map): the cells within :data:`AT_DISTANCE` of it, or the cell nearest it
    on a coarser grid, the nearest weighted most: a spot a plan has chosen (a place
    setting), whose height and checks still come from the other keys (``on``, ``for_``)."""
    cx, cy, _ = query.point(value, "at")
    x, y = query.centres()
    reach = max(AT_DISTANCE, query.grid.resolution * 0.75)
    return CostLayer(np.clip(1.0 - np.hypot(x - cx, y - cy) / reach, 0.0, 1.0))

"""The area plans work in: the box of the world's obstacles (and given points), grown.

A goal for the base, or a point a location is searched round, farther outside that box
than :data:`AREA_MARGIN` is no place the robot can mean to go: a typo in a coordinate, a
pose in another frame or unit. Grids and dense checks grow with the distance to such a
goal (a base goal 10 km away took 9.1 GB), so the motion and location layers refuse it at
once, each with its own typed error naming this bound.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from robocram.world.obstacle_boxes import ObstacleBoxes

AREA_MARGIN = 10.0  # [m] how far outside the obstacles' box a goal may lie


@dataclass(frozen=True)
class PlanningArea:
    """The box ``low`` to ``high`` (map x, y [m]) goals must lie in."""

    low: tuple[float, float]
    high: tuple[float, float]
    margin: float = AREA_MARGIN  # [m] the box was grown by this

    @classmethod
    def of(
        cls,
        obstacles: ObstacleBoxes,
        points: Iterable[tuple[float, float]] = (),
        margin: float = AREA_MARGIN,
    ) -> PlanningArea:
        """The box of ``obstacles`` and ``points`` (map x, y), grown by ``margin`` [m]."""
        xy = np.array([(float(x), float(y)) for x, y in points], dtype=float).reshape(-1, 2)
        low = np.minimum(
            xy.min(axis=0, initial=np.inf), obstacles.low[:, :2].min(axis=0, initial=np.inf)
        )
        high = np.maximum(
            xy.max(axis=0, initial=-np.inf), obstacles.high[:, :2].max(axis=0, initial=-np.inf)
        )
        if not np.isfinite(low).all():  # nothing in the world: the origin stands for it
            low, high = np.zeros(2), np.zeros(2)
        return cls(
            (float(low[0]) - margin, float(low[1]) - margin),
            (float(high[0]) + margin, float(high[1]) + margin),
            margin,
        )

    def contains(self, x: float, y: float) -> bool:
        """Whether map ``(x, y)`` [m] lies in the area (a NaN does not)."""
        return bool(self.low[0] <= x <= self.high[0] and self.low[1] <= y <= self.high[1])

    def __str__(self) -> str:
        return (
            f"x in [{self.low[0]:.2f}, {self.high[0]:.2f}], y in [{self.low[1]:.2f}, "
            f"{self.high[1]:.2f}] m (the world's obstacles grown by {self.margin:g} m, "
            "AREA_MARGIN)"
        )

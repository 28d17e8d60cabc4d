"""The fast check of a run of base poses, looked up a few poses at a time when asked.

A dense motion's chunk of poses is checked in order and stops at its first blocked pose
(about two in five of a planner's edges stop early), and poses within an exact check's
gap are not asked at all: what is never asked is never looked up. Each answer is the one
:meth:`ObstacleGrid.hits` gives for the whole run, bit for bit: the rotations are
multiplied in :meth:`ObstacleGrid.hits`' blocks (BLAS's rows change in their last bits
with the rows it is given) and only the per-pose lookups are split.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from robocram.motion.obstacle_grid import IntArray, ObstacleGrid

LOOKUP_ROWS = 32  # poses looked up together: fewer numpy calls against fewer lookups wasted


@dataclass
class GridHitsOnDemand:
    """Per pose of ``poses``, whether the fast check finds a possible collision, as
    ``grid.hits(poses, points, masks, inside)`` answers it, computed when first indexed."""

    grid: ObstacleGrid
    poses: npt.NDArray[np.float64]
    points: npt.NDArray[np.float64]
    masks: IntArray
    inside: bool
    _answers: npt.NDArray[np.bool_] = field(init=False, repr=False)
    _known: npt.NDArray[np.bool_] = field(init=False, repr=False)  # per pose: answered
    _units: dict[int, npt.NDArray[np.float64]] = field(init=False, repr=False)  # per block

    def __post_init__(self) -> None:
        count = len(self.poses)
        if self.inside:
            self._answers = np.empty(count, dtype=bool)
            self._known = np.zeros(count, dtype=bool)
        else:  # off the grid's safe part: clipped lookups, all at once (rare)
            self._answers = self.grid.hits(self.poses, self.points, self.masks, False)
            self._known = np.ones(count, dtype=bool)
        self._units = {}

    def __len__(self) -> int:
        return len(self.poses)

    def __getitem__(self, index: int) -> bool:
        if not self._known[index]:
            self._look_up(index)
        return bool(self._answers[index])

    def _look_up(self, index: int) -> None:
        """Answer the :data:`LOOKUP_ROWS` poses from ``index``'s within its block."""
        block = self.grid.block(self.points)
        start = index - index % block
        poses = self.poses[start : start + block]
        units = self._units.get(start)
        if units is None:
            units = self.grid.units(poses, self.points)
            self._units[start] = units
        first = index - start - (index - start) % LOOKUP_ROWS
        stop = min(first + LOOKUP_ROWS, len(poses))
        found = self.grid.hits_of_units(units, poses, self.masks, first, stop)
        self._answers[start + first : start + stop] = found
        self._known[start + first : start + stop] = True

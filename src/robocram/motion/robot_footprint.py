"""The robot as it stands, seen from above in its base frame: sample points with heights.

Each link (and each object the robot holds) is its box in the base frame, grown by the
contact distance. The boxes are rasterised into squares of ``spacing``; each occupied
square becomes one sample point (its centre) with the height bits of everything over it.
Placing the robot is then rotating and shifting the points; the obstacle grid, grown by
half a square's diagonal, makes one lookup per point conservative.

The **boundary** points are the squares whose bits are not all shared by their eight
neighbours. Along a densely checked motion (no point moves more than a square's width
between checks) an obstacle cannot reach the inside of the robot without first meeting
its boundary, so after one full check only the boundary needs looking at.

The **grown** points are the squares grown by a few squares along both axes, each with
the bits of every square it grows over. Where they are free at one pose, the robot is free
at every pose that moves no point of it farther than ``grown_by``: each of its squares
stays within the grown squares that are free. A long drive through open floor is then
proven free by one check per ``2 * grown_by`` of travel instead of one per centimetre.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from robocram.motion.height_bins import HeightBins
from robocram.motion.obstacle_grid import Box

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
GROWN_SQUARES = 4  # the grown footprint reaches this many squares farther


@dataclass(frozen=True)
class RobotFootprint:
    """Sample points (base frame, x y [m]) with height masks; all of them and the boundary."""

    points: FloatArray  # (n, 2)
    masks: IntArray  # (n,)
    boundary_points: FloatArray  # (m, 2)
    boundary_masks: IntArray  # (m,)
    spacing: float  # [m] side of a sample square
    reach: float  # [m] farthest any part of the robot is from the base origin (xy)
    grown_points: FloatArray  # (g, 2): the squares grown by ``grown_by``, see the module
    grown_masks: IntArray  # (g,)
    grown_by: float  # [m]
    grown_reach: float  # [m] farthest any grown square reaches from the base origin (xy)

    @property
    def dilation(self) -> float:
        """How far [m] to grow obstacles so one lookup per point is conservative."""
        return self.spacing / math.sqrt(2.0)

    @classmethod
    def build(
        cls, boxes_in_base: Sequence[Box], base_z: float, bins: HeightBins, spacing: float,
        grow: float,
    ) -> RobotFootprint:  # fmt: skip
        """Rasterise ``boxes_in_base`` (base frame) grown by ``grow`` [m]; base at ``base_z``."""
        table = np.array(boxes_in_base, dtype=float).reshape(-1, 2, 3)
        low = table[:, 0, :2] - grow
        high = table[:, 1, :2] + grow
        first = np.floor(low.min(axis=0) / spacing).astype(int)
        last = np.floor(high.max(axis=0) / spacing).astype(int)
        patch = np.zeros(tuple(last - first + 1), dtype=np.int64)
        heights = table[:, :, 2] + base_z
        every_bits = bins.masks(heights[:, 0] - grow, heights[:, 1] + grow)
        lows = (np.floor(low / spacing).astype(int) - first).tolist()
        highs = (np.floor(high / spacing).astype(int) + 1 - first).tolist()
        for bits, (i0, j0), (i1, j1) in zip(every_bits, lows, highs, strict=True):
            patch[i0:i1, j0:j1] |= bits
        padded = np.pad(patch, 1)
        inner = np.full_like(patch, -1)
        for di in (0, 1, 2):
            for dj in (0, 1, 2):
                inner &= padded[di : di + patch.shape[0], dj : dj + patch.shape[1]]
        points, masks = cls._points(patch, first, spacing)
        edge_points, edge_masks = cls._points(np.bitwise_and(patch, ~inner), first, spacing)
        reach = float(np.max(np.linalg.norm(points, axis=1))) + spacing / math.sqrt(2.0)
        grown_points, grown_masks = cls._points(
            _grown(patch, GROWN_SQUARES), first - GROWN_SQUARES, spacing
        )
        corner = spacing / math.sqrt(2.0)
        grown_reach = float(np.max(np.linalg.norm(grown_points, axis=1))) + corner
        return cls(
            points, masks, edge_points, edge_masks, spacing, reach, grown_points, grown_masks,
            GROWN_SQUARES * spacing, grown_reach,
        )  # fmt: skip

    @staticmethod
    def _points(patch: IntArray, first: npt.NDArray[np.int_], spacing: float) -> tuple[
        FloatArray, IntArray
    ]:  # fmt: skip
        i, j = np.nonzero(patch)
        centres = np.stack([(i + first[0] + 0.5) * spacing, (j + first[1] + 0.5) * spacing], 1)
        return centres.astype(float), patch[i, j]


def _grown(patch: IntArray, squares: int) -> IntArray:
    """``patch`` padded by ``squares`` on every side, each square with the bits of every
    square within ``squares`` of it along both axes (a square's grown neighbourhood)."""
    rows = np.pad(patch, squares)
    out = rows.copy()
    for d in range(1, squares + 1):
        out[d:, :] |= rows[:-d, :]
        out[:-d, :] |= rows[d:, :]
    columns = out.copy()
    for d in range(1, squares + 1):
        out[:, d:] |= columns[:, :-d]
        out[:, :-d] |= columns[:, d:]
    return out

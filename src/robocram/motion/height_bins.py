"""Heights as bits: a column of space as one 64-bit mask, one bit per height bin.

The fast base check compares what the robot occupies with what the world occupies column
by column; with heights as bits, one ``&`` of two integers says whether they share any
height in a column. Bin 0 also takes everything below the floor; what lies wholly above
the top bin is of no interest (the robot is lower than that).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]

BINS = 64  # height bins: the bits of an int64


@dataclass(frozen=True)
class HeightBins:
    """``BINS`` bins of ``height`` [m] each, from z = 0 of the map up."""

    height: float  # [m] of one bin

    @classmethod
    def up_to(cls, top: float) -> HeightBins:
        """Bins that reach ``top`` [m] (the robot's highest point) with a bin to spare."""
        return cls(max(top, 0.1) / (BINS - 1))

    def mask(self, low: float, high: float) -> np.int64:
        """The bits of the bins that ``[low, high]`` [m] meets (0 if it is above them all)."""
        first = min(max(math.floor(low / self.height), 0), BINS)
        last = min(max(math.floor(high / self.height), 0), BINS - 1)
        if first > last:
            return np.int64(0)
        bits = ((1 << (last + 1)) - 1) ^ ((1 << first) - 1)
        return np.int64(bits - (1 << 64) if bits >= 1 << 63 else bits)

    def masks(self, low: FloatArray, high: FloatArray) -> list[int]:
        """:meth:`mask` of every pair of ``low`` and ``high`` [m] (arrays of one shape), as
        Python integers: rasterising many boxes needs their bits at once."""
        first = np.minimum(np.maximum(np.floor(low / self.height), 0), BINS).astype(np.int64)
        last = np.minimum(np.maximum(np.floor(high / self.height), 0), BINS - 1).astype(np.int64)
        return [
            0 if f > t else _signed(((1 << (t + 1)) - 1) ^ ((1 << f) - 1))
            for f, t in zip(first.tolist(), last.tolist(), strict=True)
        ]


def _signed(bits: int) -> int:
    """``bits`` (0 .. 2**64 - 1) as the int64 with the same bits."""
    return bits - (1 << 64) if bits >= 1 << 63 else bits

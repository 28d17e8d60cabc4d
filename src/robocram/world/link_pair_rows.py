"""Pairs of one body's links as rows of a bounds table, worked out once per set of pairs.

A self-collision check asks about the same thousand pairs of a robot's links for every
IK candidate; turning the link names into table rows costs more than comparing the bounds,
so the handle keeps the rows per set of pairs (:meth:`WorldObject.pair_rows`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from robocram.world.sorted_unique import sorted_unique

IntArray = NDArray[np.intp]


@dataclass(frozen=True)
class LinkPairRows:
    """Per pair ``(a, b)``: both links' pybullet indices and their rows in ``used``."""

    used: tuple[int, ...]  # the link indices the pairs name, sorted: one bounds row each
    firsts: IntArray  # link index of each pair's first link
    seconds: IntArray
    cells: IntArray  # each pair's cell in a row-major (used x used) matrix

    @classmethod
    def of(cls, link_index: Mapping[str, int], pairs: Sequence[tuple[str, str]]) -> LinkPairRows:
        """The rows of ``pairs`` of link names; a name not in ``link_index`` raises KeyError."""
        firsts = np.array([link_index[a] for a, _ in pairs], dtype=np.intp)
        seconds = np.array([link_index[b] for _, b in pairs], dtype=np.intp)
        used = sorted_unique(np.concatenate([firsts, seconds]))
        cells = np.searchsorted(used, firsts) * len(used) + np.searchsorted(used, seconds)
        return cls(tuple(used.tolist()), firsts, seconds, cells)

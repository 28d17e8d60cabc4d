"""``np.unique`` of a flat array, without loading ``numpy.ma``.

NumPy 2's ``unique`` (and ``union1d``, which calls it) imports ``numpy.ma`` at its first
call, ~20 ms of a process's first motion (issue 40). For numbers without NaN, sorting
and keeping each value that differs from the one before gives the same array.
"""

from __future__ import annotations

from typing import TypeVar

import numpy as np
from numpy.typing import NDArray

__all__ = ["sorted_unique"]

T = TypeVar("T", bound=np.generic)


def sorted_unique(values: NDArray[T]) -> NDArray[T]:
    """The values of ``values`` (flattened, no NaN) sorted, each once, in their own type."""
    flat = np.sort(np.asarray(values).ravel())
    if flat.size < 2:
        return flat
    return flat[np.concatenate(([True], flat[1:] != flat[:-1]))]

"""A lazy, cached, thread-safe sequence of a designator's solutions.

A designator and every designator ``next_solution`` made from it share one stream, so a
solution is computed once, only when first asked for, whoever asks for it.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from typing import Generic, TypeVar

S = TypeVar("S")


class SolutionStream(Generic[S]):
    """Pull solutions from an iterator on demand and remember them.

    >>> s = SolutionStream(iter("ab"))
    >>> s.get(1), s.get(2)
    (('b',), None)
    """

    def __init__(self, source: Iterator[S]) -> None:
        self._source = source
        self._cache: list[S] = []
        self._exhausted = False
        self._lock = threading.Lock()

    def get(self, index: int) -> tuple[S] | None:
        """Return ``(solution,)`` for solution ``index`` (boxed: None is a solution too), or
        None past the end."""
        if index < 0:
            raise IndexError(f"solution index must be >= 0, got {index}")
        with self._lock:
            while len(self._cache) <= index and not self._exhausted:
                try:
                    self._cache.append(next(self._source))
                except StopIteration:
                    self._exhausted = True
            if index < len(self._cache):
                return (self._cache[index],)
            return None

    @property
    def computed(self) -> int:
        """How many solutions have been computed so far (laziness is observable)."""
        with self._lock:
            return len(self._cache)

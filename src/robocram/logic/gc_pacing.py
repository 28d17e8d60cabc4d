"""Collect young garbage less often while queries run, for callers that opt in.

A running query allocates terms, variables and continuation cells by the million, most
of them alive until the query backtracks or ends. CPython's cyclic collector runs its
youngest generation every 700 container allocations, and each run traverses the young
objects still alive: on the van Roy programs that costs 10-20% of the time.

The collector belongs to the whole process, so robocram leaves it alone unless asked:
queries started inside ``with fast_queries():`` (a ContextVar, so per thread and per
task) raise the youngest generation's threshold to :data:`QUERY_GEN0_THRESHOLD` (a
collection every 1,000,000 net allocations: boyer keeps about 200,000 young objects alive
per iteration, and at 100,000 the two collections traversing them took 15-25% of its time)
while at least one of them runs, and when the last one ends or suspends at an answer the
thresholds it found come back. A host that tunes the collector itself keeps its choice:
a threshold of 0 (collection off) or one above ours is never touched, and one the host
sets while a query runs is not overwritten.

>>> import gc
>>> before = gc.get_threshold()
>>> with fast_queries():
...     PACER.enter(); gc.get_threshold()[0] == QUERY_GEN0_THRESHOLD; PACER.leave()
True
>>> gc.get_threshold() == before
True
"""

from __future__ import annotations

import gc
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

__all__ = [
    "NO_PACING",
    "PACER",
    "QUERY_GEN0_THRESHOLD",
    "GcPacer",
    "NoPacing",
    "current_pacer",
    "fast_queries",
]

QUERY_GEN0_THRESHOLD = 1_000_000

_FAST_QUERIES: ContextVar[bool] = ContextVar("robocram_fast_queries", default=False)


@contextmanager
def fast_queries() -> Iterator[None]:
    """Let queries started in this block pace the cyclic collector (module docstring)."""
    token = _FAST_QUERIES.set(True)
    try:
        yield
    finally:
        _FAST_QUERIES.reset(token)


class GcPacer:
    """Counts the paced queries running in the process; the first raises, the last restores."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._running = 0
        self._saved: tuple[int, ...] = ()

    def enter(self) -> None:
        """Count a query as running; the first one raises the youngest generation's threshold."""
        with self._lock:
            if self._running == 0:
                self._saved = gc.get_threshold()
                if self._saved[0] and self._saved[0] < QUERY_GEN0_THRESHOLD:  # 0: disabled
                    gc.set_threshold(QUERY_GEN0_THRESHOLD, *self._saved[1:])
            self._running += 1

    def leave(self) -> None:
        """Count a query as stopped; the last one restores the thresholds it found."""
        with self._lock:
            self._running -= 1
            if self._running == 0 and gc.get_threshold()[0] == QUERY_GEN0_THRESHOLD:
                gc.set_threshold(*self._saved)


# The collector is one per process, so is the count of paced queries running.
PACER = GcPacer()


class NoPacing(GcPacer):
    """The default: queries leave the collector as the host set it."""

    def enter(self) -> None:
        """Do nothing."""

    def leave(self) -> None:
        """Do nothing."""


NO_PACING = NoPacing()


def current_pacer() -> GcPacer:
    """:data:`PACER` inside ``with fast_queries():``, else :data:`NO_PACING`."""
    return PACER if _FAST_QUERIES.get() else NO_PACING

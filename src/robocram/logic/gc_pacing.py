"""Collect young garbage less often while queries run.

A running query allocates terms, variables and continuation cells by the million, most
of them alive until the query backtracks or ends. CPython's cyclic collector runs its
youngest generation every 700 container allocations, and each run traverses the young
objects still alive: on the van Roy programs that costs 10-20% of the time. While at
least one query runs in the process, the youngest generation's threshold is raised to
`QUERY_GEN0_THRESHOLD` (a collection every 100,000 net allocations, a few MB of young
objects); when the last running query ends or suspends at an answer, the previous
thresholds come back. The collector is process-wide, so the count of running queries is
too (guarded by a lock for queries in several threads).

>>> import gc
>>> before = gc.get_threshold()
>>> enter(); gc.get_threshold()[0] == QUERY_GEN0_THRESHOLD; leave()
True
>>> gc.get_threshold() == before
True
"""

from __future__ import annotations

import gc
import threading

__all__ = ["QUERY_GEN0_THRESHOLD", "enter", "leave"]

QUERY_GEN0_THRESHOLD = 100_000

_lock = threading.Lock()
_running = 0
_saved: tuple[int, ...] = ()


def enter() -> None:
    """Count a query as running; the first one raises the youngest generation's threshold."""
    global _running, _saved
    with _lock:
        if _running == 0:
            _saved = gc.get_threshold()
            if _saved[0] and _saved[0] < QUERY_GEN0_THRESHOLD:  # 0: collection disabled
                gc.set_threshold(QUERY_GEN0_THRESHOLD, *_saved[1:])
        _running += 1


def leave() -> None:
    """Count a query as stopped; the last one restores the thresholds it found."""
    global _running
    with _lock:
        _running -= 1
        if _running == 0 and gc.get_threshold()[0] == QUERY_GEN0_THRESHOLD:
            gc.set_threshold(*_saved)

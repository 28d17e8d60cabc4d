"""Watching the costmaps that location designators are resolved through.

A trace or a viewer wants to show *why* a robot stood where it did: the costmap behind the
pose. ``with observing_costmaps(observer):`` calls ``observer(designator, costmap)`` each
time :class:`~robocram.costmaps.CostmapLocations` builds one inside the block (also in
threads started there, which copy the context). Observers only look: they must not
change the costmap, so resolving gives the same poses watched or not.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any

from robocram.costmaps.costmap import Costmap
from robocram.costmaps.errors import CostmapUsageError

CostmapObserver = Callable[[Any, Costmap], None]
"""Called with the location designator being resolved and the costmap built for it."""

_OBSERVERS: ContextVar[tuple[CostmapObserver, ...]] = ContextVar(
    "robocram_costmap_observers", default=()
)


@contextmanager
def observing_costmaps(observer: CostmapObserver) -> Iterator[CostmapObserver]:
    """Call ``observer`` with every costmap built for a location inside the block."""
    if not callable(observer):
        raise CostmapUsageError(f"observing_costmaps() needs a callable, got {observer!r}")
    token = _OBSERVERS.set((*_OBSERVERS.get(), observer))
    try:
        yield observer
    finally:
        _OBSERVERS.reset(token)


def notify_costmap(designator: object, costmap: Costmap) -> None:
    """Show ``costmap``, built for ``designator``, to the observers of this context."""
    for observer in _OBSERVERS.get():
        observer(designator, costmap)

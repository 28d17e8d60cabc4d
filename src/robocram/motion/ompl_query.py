"""What every OMPL query here shares: one lock, a seed, and a counted budget a stop ends.

OMPL's random numbers are one generator per process, so queries take :data:`OMPL_LOCK`
and reseed first: the same query and seed give the same path whatever ran before. A
query ends when its counted budget is spent (never by time, so load does not change the
answer) or when the running task is stopped: the stop is caught inside OMPL's callback,
ends the query at once, and is raised again once OMPL has returned.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import TYPE_CHECKING

from robocram.execution import checkpoint
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    from ompl import base as ob
    from ompl import util as ou
else:
    ob = LazyLibrary("ompl.base")
    ou = LazyLibrary("ompl.util")

OMPL_LOCK = threading.Lock()  # OMPL's random number generator is one per process
POLLS_PER_CHECK = 4  # termination polls allowed per budgeted check (OMPL may poll idly)


class OmplQuery:
    """One seeded query under :data:`OMPL_LOCK`; ``spent()`` says when its budget is gone."""

    def __init__(self, seed: int, spent: Callable[[], bool], polls: int) -> None:
        self.seed = seed
        self._spent = spent
        self._polls_left = polls
        self._stop: BaseException | None = None

    def __enter__(self) -> OmplQuery:
        OMPL_LOCK.acquire()
        ou.setLogLevel(ou.LOG_NONE)
        ou.RNG.setSeed(self.seed + 1)  # OMPL ignores a seed of 0
        return self

    def __exit__(self, *exc: object) -> None:
        OMPL_LOCK.release()
        if self._stop is not None and exc[0] is None:
            raise self._stop

    def _done(self) -> bool:
        self._polls_left -= 1
        try:
            checkpoint()
        except BaseException as stop:  # noqa: BLE001 - carried out of OMPL, raised on exit
            self._stop = stop
            return True
        return self._polls_left < 0 or self._spent()

    def condition(self, spent: Callable[[], bool] | None = None) -> ob.PlannerTerminationCondition:
        """The termination condition to pass to ``solve`` or ``simplifySolution``;
        ``spent`` replaces the budget from here on (a simplifier's own share)."""
        if spent is not None:
            self._spent = spent
        return ob.PlannerTerminationCondition(self._done)

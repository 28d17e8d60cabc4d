"""Stopping a running query: inference and time limits, and the task stop hook.

The machine counts inferences and every `CHECK_EVERY` of them checks its limits and calls
the stop hook of the current context. The execution layer installs its `checkpoint` as
that hook while a task runs (`checking_stop`), so `TopLevel.stop()` also ends a query
that loops (`p :- p.`). The hook's exception passes through `catch/3` untouched.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar

from robocram.logic.errors import InferenceLimitExceeded, TimeLimitExceeded

__all__ = ["CHECK_EVERY", "Budget", "QueryStopped", "checking_stop", "current_stop_check"]

CHECK_EVERY = 2048  # inferences between checks: rare enough to cost nothing measurable

_STOP_CHECK: ContextVar[Callable[[], None] | None] = ContextVar(
    "robocram_logic_stop_check", default=None
)


@contextmanager
def checking_stop(check: Callable[[], None]) -> Iterator[None]:
    """Call `check()` from every query run inside the block, every CHECK_EVERY inferences.

    `check` stops the query by raising; the query's caller receives that exception.
    """
    token = _STOP_CHECK.set(check)
    try:
        yield
    finally:
        _STOP_CHECK.reset(token)


def current_stop_check() -> Callable[[], None] | None:
    """The stop hook installed for this context, if any."""
    return _STOP_CHECK.get()


class QueryStopped(BaseException):
    """Carries the stop hook's exception out of the engine, past catch/3 (not an Exception)."""

    def __init__(self, original: BaseException) -> None:
        super().__init__(str(original))
        self.original = original


class Budget:
    """One query's limits: inferences, seconds, and the stop hook."""

    __slots__ = ("deadline", "inferences", "max_inferences", "stop", "time_limit")

    def __init__(self, max_inferences: int | None, time_limit: float | None) -> None:
        if max_inferences is not None and max_inferences < 0:
            raise ValueError(f"max_inferences must be >= 0, got {max_inferences}")
        if time_limit is not None and not (math.isfinite(time_limit) and time_limit >= 0):
            raise ValueError(
                f"time_limit must be a finite number >= 0 [s], got {time_limit}; "
                "pass None for no limit"
            )
        self.inferences = 0
        self.max_inferences = max_inferences
        self.time_limit = time_limit  # [s]
        self.deadline = None if time_limit is None else time.monotonic() + time_limit
        self.stop = current_stop_check()

    def spend(self, n: int) -> None:
        """Count `n` inferences; raise when a limit is passed or the hook says stop."""
        self.inferences += n
        if self.max_inferences is not None and self.inferences > self.max_inferences:
            raise InferenceLimitExceeded(self.max_inferences)
        if self.deadline is not None and time.monotonic() > self.deadline:
            raise TimeLimitExceeded(self.time_limit or 0.0)
        if self.stop is not None:
            try:
                self.stop()
            except BaseException as err:
                raise QueryStopped(err) from err

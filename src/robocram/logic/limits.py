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

from robocram.logic.errors import (
    InferenceLimitExceeded,
    PrologThrow,
    TimeLimitExceeded,
)
from robocram.logic.usage_errors import LogicArgumentError

__all__ = [
    "CHECK_EVERY",
    "PROC_LOOPS",
    "TICK",
    "Budget",
    "QueryStopped",
    "checking_stop",
    "current_stop_check",
]

CHECK_EVERY = 2048  # inferences between checks: rare enough to cost nothing measurable
PROC_LOOPS = 256  # loops a compiled procedure runs in its own frame before it reports them
TICK = 0.005  # [s] aim for a clock reading this often while a time limit runs
FIRST_CHECK = 16  # inferences before the first check of a time limit

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
    """One query's limits: inferences, seconds, the stop hook, and nested Prolog limits.

    The machine calls `spend(n)` every `n` inferences, `n` being what the previous call
    returned: at most CHECK_EVERY, fewer near an inference limit, and fewer when a time
    limit is set and inferences are slow, so that the clock is read about every TICK
    seconds (a time limit is then overshot by about TICK plus one inference). Long
    built-ins call `check()` as they go. `call_with_inference_limit/3` and
    `call_with_time_limit/2` push limits with `push_inferences` and `push_deadline`.
    """

    __slots__ = (
        "deadline",
        "every",
        "frames",
        "inferences",
        "last_clock",
        "limit_at",
        "max_inferences",
        "query_deadline",
        "stop",
        "time_frames",
        "time_limit",
    )

    def __init__(self, max_inferences: int | None, time_limit: float | None) -> None:
        if max_inferences is not None and max_inferences < 0:
            raise LogicArgumentError(f"max_inferences must be >= 0, got {max_inferences}")
        if time_limit is not None and not (math.isfinite(time_limit) and time_limit >= 0):
            raise LogicArgumentError(
                f"time_limit must be a finite number >= 0 [s], got {time_limit}; "
                "pass None for no limit"
            )
        self.inferences = 0
        self.max_inferences = max_inferences
        self.time_limit = time_limit  # [s]
        self.last_clock = time.monotonic()  # [s]
        self.query_deadline = None if time_limit is None else self.last_clock + time_limit
        self.deadline = self.query_deadline  # the earliest deadline in force [s]
        self.frames: list[float] = []  # absolute inference counts of Prolog limits
        self.time_frames: list[float] = []  # deadlines of call_with_time_limit/2 [s]
        self.limit_at = math.inf if max_inferences is None else float(max_inferences)
        # With a time limit, start checking often and double the interval while the
        # inferences turn out fast: slow ones then cannot overshoot before the first check.
        self.every = CHECK_EVERY if self.deadline is None else FIRST_CHECK
        self.stop = current_stop_check()

    def spend(self, n: int) -> int:
        """Count `n` inferences; raise when a limit is passed or the hook says stop.

        Returns how many inferences to run before the next call.
        """
        self.inferences += n
        if self.inferences > self.limit_at:
            self._over_inferences()
        if self.deadline is not None:
            now = time.monotonic()
            if now > self.deadline:
                self._over_time()
            gap = now - self.last_clock
            self.last_clock = now
            if gap > TICK:  # slow inferences: read the clock sooner
                self.every = max(1, int(self.every * TICK / gap))
            elif gap < TICK / 4 and self.every < CHECK_EVERY:
                self.every = min(CHECK_EVERY, 2 * self.every)
        if self.stop is not None:
            _ask_stop(self.stop)
        return self.interval()

    def interval(self) -> int:
        """Inferences to run before the next `spend` (at least 1)."""
        room = self.limit_at - self.inferences
        if room >= self.every:
            return self.every
        if room > 0:
            return int(room)
        if self.max_inferences is not None and self.inferences > self.max_inferences:
            return self.every  # past the query's own limit: a caught error may run on
        return 1

    def check(self) -> None:
        """Check the time limits and the stop hook without counting (for long built-ins)."""
        if self.deadline is not None and time.monotonic() > self.deadline:
            self._over_time()
        if self.stop is not None:
            _ask_stop(self.stop)

    def push_inferences(self, limit: int) -> float:
        """Start a Prolog inference limit of `limit` more inferences; return its mark."""
        mark = float(self.inferences + limit)
        self.frames.append(mark)
        self.limit_at = min(self.limit_at, mark)
        return mark

    def pop_inferences(self, mark: float) -> bool:
        """End the limit `mark`; True when it was passed."""
        if mark in self.frames:
            self.frames.remove(mark)
        self._reset_limit()
        return self.inferences > mark

    def push_deadline(self, seconds: float) -> float:
        """Start a Prolog time limit of `seconds`; return its deadline."""
        deadline = time.monotonic() + seconds
        self.time_frames.append(deadline)
        self._reset_deadline()
        return deadline

    def pop_deadline(self, deadline: float) -> None:
        """End the time limit `deadline`."""
        if deadline in self.time_frames:
            self.time_frames.remove(deadline)
        self._reset_deadline()

    def _reset_limit(self) -> None:
        own = math.inf if self.max_inferences is None else float(self.max_inferences)
        self.limit_at = min([own, *self.frames])

    def _reset_deadline(self) -> None:
        times = (
            self.time_frames
            if self.query_deadline is None
            else [
                self.query_deadline,
                *self.time_frames,
            ]
        )
        self.deadline = min(times) if times else None
        if self.deadline is not None:
            self.every = min(self.every, FIRST_CHECK)  # learn the inference speed again

    def _over_inferences(self) -> None:
        if self.max_inferences is not None and self.inferences > self.max_inferences:
            raise InferenceLimitExceeded(self.max_inferences)
        # A Prolog limit: thrown once into the goal; its call_with_inference_limit ends it.
        self.frames = [f for f in self.frames if f >= self.inferences]
        self._reset_limit()
        raise PrologThrow("inference_limit_exceeded")

    def _over_time(self) -> None:
        now = time.monotonic()
        if self.query_deadline is not None and now > self.query_deadline:
            raise TimeLimitExceeded(self.time_limit or 0.0)
        self.time_frames = [d for d in self.time_frames if d >= now]  # each fires once
        self._reset_deadline()
        raise PrologThrow("time_limit_exceeded")


def _ask_stop(stop: Callable[[], None]) -> None:
    """Call the stop hook; its exception leaves the engine as QueryStopped."""
    try:
        stop()
    except BaseException as err:
        raise QueryStopped(err) from err

"""Fluents: values that change over time and that plans wait on.

A fluent holds a value behind a Condition. Waiting is a stop point. Derived fluents
(``fl < 3``, ``fl + other``, ``fl.eq(x)``, ``fl_and(a, b)``) recompute whenever a source
changes or pulses, so they can be waited on like any other. ``==`` keeps Python's
identity meaning (fluents are dict keys); use ``fl.eq(x)`` for a derived equality.
A fluent refuses ``bool()``: ``if fl < 3:`` would always be true, use ``.get()``.
"""

from __future__ import annotations

import itertools
import operator
import threading
import weakref
from collections.abc import Callable
from typing import Any

from robocram.execution.errors import ExecutionUsageError
from robocram.execution.failures import FluentWaitTimeout
from robocram.execution.task_context import wait_until

_ids = itertools.count(1)


def _same(old: object, new: object) -> bool:
    if old is new:
        return True
    try:
        return bool(old == new)
    except (TypeError, ValueError):  # e.g. numpy arrays compare element-wise
        return False


class Fluent:
    """A thread-safe value to wait on; ``value`` reads and writes it."""

    def __init__(self, value: object = None, name: str | None = None) -> None:
        self.name = name or f"fluent-{next(_ids)}"
        self._cond = threading.Condition()
        self._value = value
        self._generation = 0  # counts changes and pulses
        self._dependents: list[weakref.ref[Fluent]] = []
        self._compute: Callable[[], object] | None = None
        self._recompute_lock = threading.Lock()

    def __repr__(self) -> str:
        return f"Fluent({self.name!r}, {self.get()!r})"

    def __bool__(self) -> bool:
        raise ExecutionUsageError(
            f"the truth of fluent {self.name!r} changes over time; "
            f"use .get() for its value now or .wait_for() to wait until it holds"
        )

    __hash__ = object.__hash__

    def get(self) -> Any:
        """The current value."""
        with self._cond:
            return self._value

    def set(self, value: object) -> None:
        """Change the value; waiters and derived fluents see it if it differs."""
        if self._compute is not None:
            raise ExecutionUsageError(
                f"fluent {self.name!r} is derived; set its source fluents instead"
            )
        self._assign(value, pulse=False)

    @property
    def value(self) -> Any:
        """The current value (assignable, like ``set``)."""
        return self.get()

    @value.setter
    def value(self, value: object) -> None:
        self.set(value)

    @property
    def generation(self) -> int:
        """How many changes and pulses the fluent has seen."""
        with self._cond:
            return self._generation

    def pulse(self) -> None:
        """Wake waiters and ``whenever`` loops without changing the value."""
        if self._compute is not None:
            self._recompute(pulse=True)
            return
        with self._cond:
            self._generation += 1
            self._cond.notify_all()
        self._notify_dependents(pulse=True)

    def _assign(self, value: object, pulse: bool) -> None:
        with self._cond:
            changed = not _same(self._value, value)
            self._value = value
            if changed or pulse:
                self._generation += 1
                self._cond.notify_all()
        if changed or pulse:
            self._notify_dependents(pulse and not changed)

    def _notify_dependents(self, pulse: bool) -> None:
        for ref in list(self._dependents):
            dependent = ref()
            if dependent is not None:
                dependent._recompute(pulse)

    def _recompute(self, pulse: bool) -> None:
        if self._compute is None:
            return
        with self._recompute_lock:  # so concurrent source changes land in order
            self._assign(self._compute(), pulse)

    def wait_for(
        self, predicate: Callable[[Any], object] | None = None, timeout: float | None = None
    ) -> Any:
        """Wait until the value is truthy (or satisfies ``predicate``); return that value.

        Raises FluentWaitTimeout after ``timeout`` [s]; a stop point.
        """
        test = predicate or bool
        seen: list[object] = []

        def ready() -> bool:
            if test(self._value):
                seen.append(self._value)
                return True
            return False

        if not wait_until(self._cond, ready, timeout):
            raise FluentWaitTimeout(fluent=self.name, timeout=timeout, value=self.get())
        return seen[-1]

    def wait_for_update(self, after: int, timeout: float | None = None) -> tuple[Any, int]:
        """Wait until ``generation`` exceeds ``after``; return ``(value, generation)``."""
        seen: list[tuple[object, int]] = []

        def ready() -> bool:
            if self._generation > after:
                seen.append((self._value, self._generation))
                return True
            return False

        if not wait_until(self._cond, ready, timeout):
            raise FluentWaitTimeout(fluent=self.name, timeout=timeout, value=self.get())
        return seen[-1]

    def eq(self, other: object) -> Fluent:
        """A fluent that is True while this value equals ``other``."""
        return derive(operator.eq, self, other, name=f"({self.name} == {_label(other)})")

    def ne(self, other: object) -> Fluent:
        """A fluent that is True while this value differs from ``other``."""
        return derive(operator.ne, self, other, name=f"({self.name} != {_label(other)})")

    def __lt__(self, other: object) -> Fluent:
        return derive(operator.lt, self, other, name=f"({self.name} < {_label(other)})")

    def __le__(self, other: object) -> Fluent:
        return derive(operator.le, self, other, name=f"({self.name} <= {_label(other)})")

    def __gt__(self, other: object) -> Fluent:
        return derive(operator.gt, self, other, name=f"({self.name} > {_label(other)})")

    def __ge__(self, other: object) -> Fluent:
        return derive(operator.ge, self, other, name=f"({self.name} >= {_label(other)})")

    def __add__(self, other: object) -> Fluent:
        return derive(operator.add, self, other, name=f"({self.name} + {_label(other)})")

    def __radd__(self, other: object) -> Fluent:
        return derive(operator.add, other, self, name=f"({_label(other)} + {self.name})")

    def __sub__(self, other: object) -> Fluent:
        return derive(operator.sub, self, other, name=f"({self.name} - {_label(other)})")

    def __rsub__(self, other: object) -> Fluent:
        return derive(operator.sub, other, self, name=f"({_label(other)} - {self.name})")

    def __mul__(self, other: object) -> Fluent:
        return derive(operator.mul, self, other, name=f"({self.name} * {_label(other)})")

    def __rmul__(self, other: object) -> Fluent:
        return derive(operator.mul, other, self, name=f"({_label(other)} * {self.name})")

    def __truediv__(self, other: object) -> Fluent:
        return derive(operator.truediv, self, other, name=f"({self.name} / {_label(other)})")

    def __neg__(self) -> Fluent:
        return derive(operator.neg, self, name=f"(-{self.name})")


def _label(value: object) -> str:
    return value.name if isinstance(value, Fluent) else repr(value)


def derive(fn: Callable[..., object], *sources: object, name: str | None = None) -> Fluent:
    """A fluent whose value is ``fn(*values of sources)``; constants are passed as they are."""

    def compute() -> object:
        return fn(*(s.get() if isinstance(s, Fluent) else s for s in sources))

    derived = Fluent(compute(), name)
    derived._compute = compute
    for source in sources:
        if isinstance(source, Fluent):
            with source._cond:  # drop fluents derived earlier and since collected
                live = [ref for ref in source._dependents if ref() is not None]
                source._dependents = [*live, weakref.ref(derived)]
    derived._recompute(False)  # catch a source change between compute() and registration
    return derived


def fl_and(*sources: object) -> Fluent:
    """True while every source value is truthy."""
    return derive(lambda *v: all(v), *sources, name=_joined("and", sources))


def fl_or(*sources: object) -> Fluent:
    """True while any source value is truthy."""
    return derive(lambda *v: any(v), *sources, name=_joined("or", sources))


def fl_not(source: object) -> Fluent:
    """True while the source value is falsy."""
    return derive(operator.not_, source, name=f"(not {_label(source)})")


def _joined(word: str, sources: tuple[object, ...]) -> str:
    return "(" + f" {word} ".join(_label(s) for s in sources) + ")"

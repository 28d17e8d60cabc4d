"""The table of built-in predicates, filled by decorators in the builtin_* modules."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from robocram.logic.control import CONTROL_NAMES
from robocram.logic.predicate import CONTROL, DET, NONDET, DetFn, NondetFn, Pred

__all__ = ["BUILTINS", "det", "nondet"]

BUILTINS: dict[tuple[str, int], Pred] = {}

for _name, _arity in CONTROL_NAMES:
    BUILTINS[(_name, _arity)] = Pred(_name, _arity, CONTROL)


def _register(name: str, arities: tuple[int, ...], kind: int, fn: Any) -> None:
    for arity in arities:
        pred = Pred(name, arity, kind, fn)
        pred.system = True
        BUILTINS[(name, arity)] = pred


def det(name: str, *arities: int) -> Callable[[DetFn], DetFn]:
    """Register a deterministic built-in: `fn(machine, args) -> bool` (True = success)."""

    def decorate(fn: DetFn) -> DetFn:
        _register(name, arities, DET, fn)
        return fn

    return decorate


def nondet(name: str, *arities: int) -> Callable[[NondetFn], NondetFn]:
    """Register a nondeterministic built-in: a generator yielding True per solution."""

    def decorate(fn: NondetFn) -> NondetFn:
        _register(name, arities, NONDET, fn)
        return fn

    return decorate

"""Limits set from Prolog: call_with_time_limit/2 and call_with_inference_limit/3.

They follow SWI-Prolog's library(time) and call_with_inference_limit/3: a time limit
runs its goal as once/1 and throws `time_limit_exceeded` when the time is up; an
inference limit bounds each solution of its goal, and its result says how the goal
ended: `!` (no choicepoint left), `true` (more solutions may follow) or
`inference_limit_exceeded` (the goal was stopped by an exception of that name, which
a catch/3 inside the goal can see). Nested limits: the earliest one in force fires.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import TYPE_CHECKING

from robocram.logic.arith import evaluate
from robocram.logic.builtin_spec import Builtin, det, nondet
from robocram.logic.builtin_terms import need_int
from robocram.logic.choicepoints import ALT, CLAUSES, GEN, PROC, ChoicePoint
from robocram.logic.errors import PrologDomainError, PrologThrow
from robocram.logic.terms import deref
from robocram.logic.value import Value

if TYPE_CHECKING:
    from robocram.logic.engine import Engine

__all__: list[str] = []

Args = tuple[Value, ...]
_ALTERNATIVES = frozenset([CLAUSES, ALT, GEN, PROC])
_EXCEEDED = "inference_limit_exceeded"


def _call_with_time_limit(m: Engine, a: Args) -> bool:
    seconds = evaluate(a[0])
    if not seconds > 0:  # SWI: no time at all is already too late
        raise PrologThrow("time_limit_exceeded")
    if not math.isfinite(seconds):
        return _once(m, a[1])
    deadline = m.budget.push_deadline(float(seconds))
    try:
        return _once(m, a[1])
    finally:
        m.budget.pop_deadline(deadline)


def _once(m: Engine, goal: Value) -> bool:
    for _ in m.solve(goal, sub=True):
        return True  # the bindings stay; the abandoned search leaves no choicepoint
    return False


def _call_with_inference_limit(m: Engine, a: Args) -> Iterator[bool]:
    limit = need_int(a[1], "call_with_inference_limit/3")
    if limit < 0:
        raise PrologDomainError(
            "not_less_than_zero", limit, f"call_with_inference_limit/3: limit {limit} < 0"
        )
    cps: list[ChoicePoint] = []
    solutions = m.solve(deref(a[0]), sub=True, cps=cps)
    while True:
        mark = m.budget.push_inferences(limit)  # a fresh limit for each solution
        try:
            found = next(solutions, False) is None
        except PrologThrow as err:
            if err.ball != _EXCEEDED:
                raise
            if m.unify(a[2], _EXCEEDED):
                yield False  # the last solution
            return
        finally:
            m.budget.pop_inferences(mark)
        if not found:
            return
        more = any(cp[0] in _ALTERNATIVES for cp in cps[1:])
        if m.unify(a[2], "true" if more else "!"):
            yield more  # False: the last solution
        if not more:
            return


BUILTINS: tuple[Builtin, ...] = (
    det("call_with_time_limit", _call_with_time_limit, 2),
    nondet("call_with_inference_limit", _call_with_inference_limit, 3),
)

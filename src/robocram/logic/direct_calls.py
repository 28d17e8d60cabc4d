"""A clause's first body call made from its own code: the callee's procedure called directly.

`p(X) :- q(X, Y), r(Y).` returns the continuation `q(X, Y), r(Y)` to the machine, which
unpacks it, looks `q/2` up and calls its procedure: a goal tuple, a continuation cell and
a trip round the dispatch for one call. The caller's procedure can instead call `q`'s
procedure itself with the continuation `r(Y)` and return what it returns (a failure is
the machine's to backtrack, as before: the caller's choicepoint is pushed first).

A procedure's level is 0 without direct calls, else one more than its callees' highest;
only a callee below MAX_LEVEL is called so, so the Python stack grows by MAX_LEVEL frames
at most, whatever the program's recursion (a callee exists before its caller is
compiled: no cycle). And only while the knowledge base's generation is the one the
caller was compiled at (the callee's procedure is then the one its predicate holds);
else the caller returns the call as before (see codegen.direct_call). A callee not yet
compiled is compiled then, at level 0.
"""

from __future__ import annotations

from collections.abc import Callable
from weakref import WeakKeyDictionary

from robocram.logic.goal_writer import term_parts
from robocram.logic.inline_calls import CalleeTable, Lookup
from robocram.logic.template import Tmpl
from robocram.logic.value import Value

__all__ = ["LEVELS", "MAX_LEVEL", "callee_at", "direct_callee"]

MAX_LEVEL = 4
# Each compiled procedure's level (codegen reads it; procedure fills it).
LEVELS: WeakKeyDictionary[Callable[..., object], int] = WeakKeyDictionary()


def direct_callee(
    table: CalleeTable,
    goal: Value,
    caller: tuple[str, int],
    seen: list[Lookup] | None = None,
) -> tuple[int, Callable[..., object], int] | None:
    """(generation, procedure, its level) of the predicate `goal` calls; None when `goal`
    is no call, calls the `caller`, or its predicate has no procedure below MAX_LEVEL.
    `seen` gets the lookup made, if any."""
    parts = term_parts(goal)
    if parts is None or type(goal) is not Tmpl:
        return None
    key = (parts[0], len(parts[1]))
    if key == caller:
        return None
    found = callee_at(table, key)
    if seen is not None:
        seen.append(("direct", key, found is not None))
    return None if found is None else (table._generation, *found)


def callee_at(table: CalleeTable, key: tuple[str, int]) -> tuple[Callable[..., object], int] | None:
    """The procedure of predicate `key` a caller may call directly, and its level; None
    when it has none below MAX_LEVEL (one not compiled yet is compiled now)."""
    pred = table._preds.get(key)
    if pred is None:
        return None
    proc = pred.callee_procedure(table)
    level = LEVELS.get(proc, MAX_LEVEL) if proc is not None else MAX_LEVEL
    if proc is None or level >= MAX_LEVEL:
        return None
    return proc, level

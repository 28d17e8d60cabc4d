"""Calls of small one-clause predicates compiled into their caller's procedure.

`split(...) :- before(X, Y), !, ...` with `before(pair(A, _), pair(B, _)) :- A < B.`
costs a trip round the machine (a continuation cell, the goal dispatch, the callee's
procedure frame) for what is one comparison. A call leading a clause body (after its
inline goals) to a static predicate of one clause (no control construct in its body,
no cut but those that do nothing) is, renamed apart, the same as unifying the callee's
head arguments with the call's and running that body: its inline goals are compiled
in place, as a head and its leading tests are, and its calls join the caller's
continuation (a wrapper such as `mult(A, D, B) :- mult(A, D, 0, B).` costs no call).

The callee can change after the caller is compiled (assert, consult, abolish): the
inlined code runs only while the knowledge base's generation is the one it was compiled
at, and otherwise the caller makes the call as before (see codegen.inline_call).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Protocol

from robocram.logic.goal_writer import inlinable, slots_in, term_parts
from robocram.logic.template import Slot, Tmpl
from robocram.logic.value import Value

__all__ = ["CalleeTable", "Expansion", "Lookup", "expand_call", "inline_clause", "max_slot"]

USER_KIND = 0  # predicate.USER (not imported: predicate imports the procedure compiler)
_MAX_GOALS = 8  # a longer callee body stays a call
_CONTROL = {(",", 2), (";", 2), ("->", 2), ("*->", 2), ("\\+", 1)}  # transparent to cut


class _Clause(Protocol):
    @property
    def head(self) -> tuple[Value, ...]: ...

    @property
    def body_rev(self) -> tuple[Value, ...]: ...


class _Pred(Protocol):
    """What inlining and direct calls (see direct_calls.py) read of a predicate
    (predicate.Pred, not imported: it imports us)."""

    @property
    def kind(self) -> int: ...

    @property
    def dynamic(self) -> bool: ...

    @property
    def pyfn(self) -> object: ...

    @property
    def erased(self) -> int: ...

    @property
    def clauses(self) -> Sequence[_Clause]: ...

    def callee_procedure(self, callees: CalleeTable | None) -> Callable[..., object] | None: ...


class CalleeTable(Protocol):
    """What inlining reads of the knowledge base: its predicates and change counter."""

    @property
    def _preds(self) -> Mapping[tuple[str, int], _Pred]: ...

    @property
    def _generation(self) -> int: ...


# (the guard's generation, the goals that replace the call, slots they use past `base`)
Expansion = tuple[int, list[Value], int]
# What code generation asked of the knowledge base and found (see shared_code.py):
# ("inline", key, the one clause's head and body templates or None) or
# ("direct", key, whether a procedure is called directly).
Lookup = tuple[str, tuple[str, int], tuple[tuple[Value, ...], tuple[Value, ...]] | bool | None]


def max_slot(templates: list[Value]) -> int:
    """One past the highest slot number in `templates` (0 when there is none)."""
    found: list[int] = []
    for t in templates:
        slots_in(t, found)
    return max(found) + 1 if found else 0


def expand_call(
    table: CalleeTable,
    goal: Value,
    base: int,
    caller: tuple[str, int],
    seen: list[Lookup] | None = None,
) -> Expansion | None:
    """The goals a call of a small predicate stands for, its slots renamed from `base`
    on; None when `goal` is not such a call (or calls the `caller` itself). `seen`
    gets the lookup made, if any."""
    parts = term_parts(goal)
    if parts is None or type(goal) is not Tmpl or (parts[0], len(parts[1])) == caller:
        return None
    name, args = parts
    found = inline_clause(table, (name, len(args)))
    if seen is not None:
        seen.append(("inline", (name, len(args)), found))
    if found is None:
        return None
    clause_head, clause_body = found
    body = _without_cuts(list(reversed(clause_body)))
    if body is None:  # not reached: inline_clause checked it
        return None
    head = [_rename(h, base) for h in clause_head]
    goals: list[Value] = [Tmpl("=", (h, a)) for h, a in zip(head, args, strict=True)]
    goals += [_rename(g, base) for g in body]
    return table._generation, goals, max_slot([*clause_head, *body])


def inline_clause(
    table: CalleeTable, key: tuple[str, int]
) -> tuple[tuple[Value, ...], tuple[Value, ...]] | None:
    """The head and reversed body templates of the one clause a call of `key` may be
    replaced by; None when `key` is no small static one-clause predicate."""
    pred = table._preds.get(key)
    if pred is None or pred.kind != USER_KIND or pred.dynamic or pred.pyfn is not None:
        return None
    clauses = pred.clauses
    if len(clauses) != 1 or pred.erased:
        return None
    clause = clauses[0]
    body = _without_cuts(list(reversed(clause.body_rev)))
    if body is None or len(body) > _MAX_GOALS:
        return None
    return clause.head, clause.body_rev


def _without_cuts(body: list[Value]) -> list[Value] | None:
    """The body without its cuts, when they do nothing; None when it has another cut or
    a control construct (which a cut inside would make cut the caller's clause).

    The one clause leaves no alternative to cut, and inline goals before a cut leave
    no choicepoint, except `arg/3` with N unbound, which enumerates when it runs as a
    call (a goal that could not be compiled in). Calls (after those goals) leave the
    cut barrier alone: they are opaque to cut.
    """
    out: list[Value] = []
    for g in body:
        parts = term_parts(g)
        if parts is not None and (parts[0], len(parts[1])) in _CONTROL:
            return None
        if g == "!":
            if not all(inlinable(e) and _name(e) != "arg" for e in out):
                return None
            continue
        out.append(g)
    return out


def _name(g: Value) -> str | None:
    parts = term_parts(g)
    return parts[0] if parts is not None else None


def _rename(t: Value, base: int) -> Value:
    """Template `t` with each slot `i` made slot `base + i`."""
    if type(t) is Slot:
        return Slot(base + t.i)
    if type(t) is Tmpl:
        return Tmpl(t.name, tuple([_rename(a, base) for a in t.args]))
    return t

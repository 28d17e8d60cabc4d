"""The system predicates: control constructs and built-ins, frozen and shared read-only.

The table is built from the `BUILTINS` tuples the built-in modules list, named here one
by one, so what is built in is visible in one place and no import fills a registry.
Library predicates (written in Prolog) are not in it: each knowledge base compiles its
own copies (`library_predicates`), so the code generated for one KB's `append/3` is never
run by another. A user program may redefine a library predicate; the library's own calls
go to private twins (`'$lib:append'/3`), so other library predicates keep working.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from types import MappingProxyType

from robocram.logic import (
    builtin_arith,
    builtin_atoms,
    builtin_database,
    builtin_flags,
    builtin_limits,
    builtin_lists,
    builtin_solutions,
    builtin_terms,
    builtin_text,
    builtin_write,
    python_predicates,
)
from robocram.logic.builtin_spec import Builtin
from robocram.logic.clause import Clause
from robocram.logic.control import CONTROL_NAMES
from robocram.logic.fact_groups import LIBRARY_OWNER
from robocram.logic.keys import pred_key
from robocram.logic.library import LIBRARY
from robocram.logic.loader import compile_clause
from robocram.logic.predicate import CONTROL, FrozenPred, Key, Pred
from robocram.logic.reader import read_terms
from robocram.logic.terms import Term
from robocram.logic.usage_errors import LogicArgumentError
from robocram.logic.value import Value

__all__ = ["PRIVATE_PREFIX", "library_predicates", "system_predicates"]

PRIVATE_PREFIX = "$lib:"
_CONTROL_ARGS = {(",", 2), (";", 2), ("->", 2), ("*->", 2), ("\\+", 1)}
_TABLES: tuple[tuple[Builtin, ...], ...] = (
    builtin_arith.BUILTINS,
    builtin_atoms.BUILTINS,
    builtin_database.BUILTINS,
    builtin_flags.BUILTINS,
    builtin_limits.BUILTINS,
    builtin_lists.BUILTINS,
    builtin_solutions.BUILTINS,
    builtin_terms.BUILTINS,
    builtin_text.BUILTINS,
    builtin_write.BUILTINS,
    python_predicates.BUILTINS,
)


@cache
def system_predicates() -> Mapping[Key, Pred]:
    """Control constructs and built-ins by name/arity (a read-only view, built once)."""
    table: dict[Key, Pred] = {}
    for name, arity in CONTROL_NAMES:
        table[pred_key(name, arity)] = FrozenPred(name, arity, CONTROL)
    for builtins in _TABLES:
        for b in builtins:
            for arity in b.arities:
                if (b.name, arity) in table:
                    raise LogicArgumentError(f"built-in {b.name}/{arity} is listed twice")
                table[pred_key(b.name, arity)] = FrozenPred(b.name, arity, b.kind, b.fn)
    return MappingProxyType(table)


@cache
def _library_clauses() -> tuple[tuple[Key, Clause], ...]:
    """The library, read and compiled once: each predicate and its private twin."""
    terms = [term for term, _ in read_terms(LIBRARY)]
    names = {_key(_head(t)) for t in terms}
    out: list[tuple[Key, Clause]] = []
    for term in terms:
        head = _head(term)
        body = _private_calls(term[1][1], names) if _is_rule(term) else "true"
        for name in (head if type(head) is str else head[0], None):
            if name is None:
                name = PRIVATE_PREFIX + _key(head)[0]
            renamed = Term(name, head[1]) if type(head) is Term else name
            out.append(compile_clause(Term(":-", (renamed, body)), LIBRARY_OWNER))
    return tuple(out)


def _is_rule(t: Value) -> bool:
    return type(t) is Term and t[0] == ":-" and len(t[1]) == 2


def _head(t: Value) -> Value:
    return t[1][0] if _is_rule(t) else t


def _key(t: Value) -> Key:
    return (t, 0) if type(t) is str else (t[0], len(t[1]))


def _private_calls(goal: Value, names: set[Key]) -> Value:
    """Point the body's calls of library predicates at their private twins."""
    if type(goal) not in (str, Term):
        return goal
    key = _key(goal)
    if key in _CONTROL_ARGS:
        return Term(goal[0], tuple(_private_calls(g, names) for g in goal[1]))
    if key not in names:
        return goal
    name = PRIVATE_PREFIX + key[0]
    return Term(name, goal[1]) if type(goal) is Term else name


def library_predicates() -> dict[Key, Pred]:
    """Fresh library predicates for one knowledge base (own clauses, own compiled code)."""
    preds: dict[Key, Pred] = {}
    for key, c in _library_clauses():
        pred = preds.get(key)
        if pred is None:
            pred = preds[key] = Pred(key[0], key[1])
            pred.owner = LIBRARY_OWNER
        pred.add_last(Clause(c.head, c.body_rev, c.nvars, c.group, c.source, c.name))
    return preds

"""The system predicates: control constructs and built-ins, frozen and shared read-only.

The table is built from the `BUILTINS` tuples the built-in modules list, named here one
by one, so what is built in is visible in one place and no import fills a registry.
Library predicates (written in Prolog) are not in it: each knowledge base compiles its
own copies (`library_predicates`), so the code generated for one KB's `append/3` is never
run by another.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from types import MappingProxyType

from robocram.logic import (
    builtin_arith,
    builtin_atoms,
    builtin_database,
    builtin_lists,
    builtin_solutions,
    builtin_terms,
    python_predicates,
)
from robocram.logic.builtin_spec import Builtin
from robocram.logic.clause import Clause
from robocram.logic.control import CONTROL_NAMES
from robocram.logic.library import LIBRARY
from robocram.logic.loader import compile_clause
from robocram.logic.predicate import CONTROL, FrozenPred, Key, Pred
from robocram.logic.reader import read_terms

__all__ = ["LIBRARY_OWNER", "library_predicates", "system_predicates"]

LIBRARY_OWNER = "library"
_TABLES: tuple[tuple[Builtin, ...], ...] = (
    builtin_arith.BUILTINS,
    builtin_atoms.BUILTINS,
    builtin_database.BUILTINS,
    builtin_lists.BUILTINS,
    builtin_solutions.BUILTINS,
    builtin_terms.BUILTINS,
    python_predicates.BUILTINS,
)


@cache
def system_predicates() -> Mapping[Key, Pred]:
    """Control constructs and built-ins by name/arity (a read-only view, built once)."""
    table: dict[Key, Pred] = {}
    for name, arity in CONTROL_NAMES:
        table[(name, arity)] = FrozenPred(name, arity, CONTROL)
    for builtins in _TABLES:
        for b in builtins:
            for arity in b.arities:
                if (b.name, arity) in table:
                    raise ValueError(f"built-in {b.name}/{arity} is listed twice")
                table[(b.name, arity)] = FrozenPred(b.name, arity, b.kind, b.fn)
    return MappingProxyType(table)


@cache
def _library_clauses() -> tuple[tuple[Key, Clause], ...]:
    """The library text, read and compiled once; only its templates are shared."""
    return tuple(compile_clause(term, LIBRARY_OWNER) for term, _ in read_terms(LIBRARY))


def library_predicates() -> dict[Key, Pred]:
    """Fresh library predicates for one knowledge base (own clauses, own compiled code)."""
    preds: dict[Key, Pred] = {}
    for key, c in _library_clauses():
        pred = preds.get(key)
        if pred is None:
            pred = preds[key] = Pred(key[0], key[1])
            pred.system = True
            pred.owner = LIBRARY_OWNER
        pred.clauses.append(Clause(c.head, c.body_rev, c.nvars, c.group, c.source, c.name))
    return preds

"""Cyclic terms (`X = f(X)`) met by built-ins that walk a term: one typed error, found cheaply.

Unification handles cyclic terms; built-ins that copy, collect or print a term cannot, and
raise `resource_error(term_depth)` (a `PrologResourceError`, as for a term too deep for
the engine) instead of looping and eating memory. Walkers stay fast on ordinary terms:
lists are checked with Brent's cycle test (one identity test per cell), other walkers
run `is_acyclic` once, only after `WALK_STEPS` steps.
"""

from __future__ import annotations

from collections.abc import Callable

from robocram.logic.acyclic import is_acyclic
from robocram.logic.errors import PrologResourceError
from robocram.logic.terms import Term, Var
from robocram.logic.value import Value

__all__ = ["WALK_STEPS", "check_acyclic", "cyclic_error", "is_acyclic", "list_prefix"]

WALK_STEPS = 100_000  # steps a walker takes before it checks its term for cycles once
_NO_CELL = object()


def cyclic_error(what: str) -> PrologResourceError:
    """The error for a cyclic term where `what` needs a finite one."""
    return PrologResourceError(
        "term_depth",
        f"{what}: the term is cyclic (as after X = f(X)); test it with acyclic_term/1 first",
    )


def check_acyclic(t: Value, what: str) -> None:
    """Raise `cyclic_error(what)` when `t` is cyclic."""
    if not is_acyclic(t):
        raise cyclic_error(what)


def list_prefix(
    t: Value, what: str, check: Callable[[], None] | None = None
) -> tuple[list[Value], Value]:
    """The elements of the list cells of `t` and the dereferenced tail after them.

    Raises `cyclic_error(what)` for a cyclic list (`L = [a|L]`), found by Brent's test.
    `check` (the query's limit check) is called every 32768 cells of a long list.

    >>> list_prefix(Term(".", (1, Term(".", (2, "[]")))), "t")
    ([1, 2], '[]')
    """
    items: list[Value] = []
    while type(t) is Var and t.ref is not None:
        t = t.ref
    saved: object = _NO_CELL
    power = 64
    while type(t) is Term and t[0] == "." and len(t[1]) == 2:
        items.append(t[1][0])
        t = t[1][1]
        while type(t) is Var and t.ref is not None:
            t = t.ref
        if t is saved:
            raise cyclic_error(what)
        if len(items) == power:  # Brent: move the marker to the hare every power of two
            saved = t
            power <<= 1
        if check is not None and not len(items) & 0x7FFF:
            check()
    return items, t

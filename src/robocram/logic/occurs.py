"""Unification with the occurs check, for the `occurs_check` flag (true or error).

With the flag `true` a unification that would bind a variable to a term containing it
fails; with `error` it raises `error(occurs_check(Var, Term), _)`, as SWI-Prolog does.
Both walk the terms with an explicit stack, so any depth is fine.

>>> x = Var(); unify_checked(x, Term("f", (x,)), [], error=False)
False
"""

from __future__ import annotations

from robocram.logic.errors import PrologOccursCheckError
from robocram.logic.terms import Term, Var
from robocram.logic.unify import unify_iterative
from robocram.logic.value import Value

__all__ = ["occurs_in", "unify_checked"]


def occurs_in(v: Var, t: Value) -> bool:
    """True when unbound variable `v` occurs in term `t` (bindings followed)."""
    seen: set[int] = set()
    stack = [t]
    while stack:
        t = stack.pop()
        while type(t) is Var and t.ref is not None:
            t = t.ref
        if t is v:
            return True
        if type(t) is Term and id(t) not in seen:
            seen.add(id(t))  # a cyclic term made earlier, with the flag false, still ends
            stack.extend(t[1])
    return False


def unify_checked(a: Value, b: Value, trail: list[Var], error: bool) -> bool:
    """Unify `a` and `b` without making cyclic terms; `error` raises instead of failing."""

    def may_bind(v: Var, t: Value) -> bool:
        if not occurs_in(v, t):
            return True
        if error:
            raise PrologOccursCheckError(v, t)
        return False

    return unify_iterative(a, b, trail, may_bind)

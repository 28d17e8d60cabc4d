"""Unification with the occurs check, for the `occurs_check` flag (true or error).

With the flag `true` a unification that would bind a variable to a term containing it
fails; with `error` it raises `error(occurs_check(Var, Term), _)`, as SWI-Prolog does.
Both walk the terms with an explicit stack, so any depth is fine.

>>> x = Var(); unify_checked(x, Term("f", (x,)), [], error=False)
False
"""

from __future__ import annotations

from typing import Any

from robocram.logic.errors import PrologOccursCheckError
from robocram.logic.terms import Term, Var
from robocram.logic.unify import unify

__all__ = ["occurs_in", "unify_checked"]


def occurs_in(v: Var, t: Any) -> bool:
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


def unify_checked(a: Any, b: Any, trail: list[Var], error: bool) -> bool:
    """Unify `a` and `b` without making cyclic terms; `error` raises instead of failing."""
    stack = [(a, b)]
    while stack:
        a, b = stack.pop()
        while type(a) is Var and a.ref is not None:
            a = a.ref
        while type(b) is Var and b.ref is not None:
            b = b.ref
        if a is b:
            continue
        if type(a) is not Var and type(b) is Var:
            a, b = b, a
        if type(a) is Var:
            if type(b) is Term and occurs_in(a, b):
                if error:
                    raise PrologOccursCheckError(a, b)
                return False
            a.ref = b
            trail.append(a)
        elif type(a) is Term:
            if type(b) is not Term or a[0] != b[0] or len(a[1]) != len(b[1]):
                return False
            stack.extend(zip(a[1], b[1], strict=True))
        elif not unify(a, b, trail):  # two constants
            return False
    return True

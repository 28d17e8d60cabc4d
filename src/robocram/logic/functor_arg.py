"""functor/3 and arg/3 split into the fast path and the checks, for built-ins and clause code.

Generated clause code runs `arg(N, T, A)` inline when N is an integer in range and T a
compound, and calls `arg_check` otherwise (which raises the ISO error or lets the goal
fail); `functor_make` builds the term of `functor(T, F, N)` with T unbound.
"""

from __future__ import annotations

from robocram.logic.errors import (
    PrologDomainError,
    PrologInstantiationError,
    PrologTypeError,
)
from robocram.logic.terms import Term, Var, make_term, make_var
from robocram.logic.value import Value

__all__ = ["arg_check", "fresh_vars", "functor_make"]


def _deref(t: Value) -> Value:
    while type(t) is Var and t.ref is not None:
        t = t.ref
    return t


def need_int(t: Value, what: str) -> int:
    """Dereference `t` and insist on an integer (the ISO errors name ``what``)."""
    t = _deref(t)
    if type(t) is Var:
        raise PrologInstantiationError(f"{what}: argument is unbound; bind it to an integer")
    if type(t) is not int:
        raise PrologTypeError("integer", t, f"{what}: {t!r} is not an integer")
    return t


def arg_check(n: Value, t: Value) -> int:
    """Raise the ISO error of `arg(N, T, _)`, or return N when the call just fails or runs.

    >>> arg_check(3, Term("f", (1,)))
    3
    """
    k = need_int(n, "arg/3")
    t = _deref(t)
    if type(t) is Var:
        raise PrologInstantiationError("arg/3: the term is unbound")
    if type(t) is not Term:
        raise PrologTypeError("compound", t, f"arg/3: {t!r} is not a compound term")
    if k < 0:
        raise PrologDomainError("not_less_than_zero", k, f"arg/3: position {k} < 0")
    return k


def fresh_vars(n: int) -> tuple[Var, ...]:
    """`n` new unbound variables; small counts spelt out (no comprehension frame to run,
    and no Python frame per variable: `make_var` and the slot set here).

    >>> len(fresh_vars(2)), len(fresh_vars(7))
    (2, 7)
    """
    if 0 < n <= 3:
        a = _new()
        a.ref = None
        if n == 1:
            return (a,)
        b = _new()
        b.ref = None
        if n == 2:
            return (a, b)
        c = _new()
        c.ref = None
        return (a, b, c)
    made = []
    for _ in range(n):
        v = _new()
        v.ref = None
        made.append(v)
    return tuple(made)


_new = make_var


def functor_make(name: Value, arity: Value) -> Value:
    """The most general term with functor name/arity (`functor(T, F, N)`, T unbound).

    >>> functor_make("f", 2).arity, functor_make("a", 0)
    (2, 'a')
    """
    name = _deref(name)
    n = _deref(arity)
    if type(name) is str and type(n) is int and n > 0:  # the common case, checked below
        return make_term((name, fresh_vars(n)))
    if type(name) is Var:
        raise PrologInstantiationError("functor/3: both the term and the name are unbound")
    n = need_int(n, "functor/3")
    if n < 0:
        raise PrologDomainError("not_less_than_zero", n, f"functor/3: arity {n} < 0")
    if type(name) is Term:
        raise PrologTypeError("atomic", name, f"functor/3: {name!r} is not atomic")
    if n == 0:
        return name
    if type(name) is not str:
        raise PrologTypeError("atom", name, f"functor/3: {name!r} cannot name a compound")
    return make_term((name, fresh_vars(n)))

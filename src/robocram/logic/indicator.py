"""Predicate indicators `Name/Arity` checked the way ISO built-ins report them.

`abolish/1` needs a complete indicator, `current_predicate/1` accepts a pattern with
unbound parts; both name the offending part in the error (`type_error(integer, a)` for
`foo/a`), not the whole indicator, except when the term is not `_/_` at all.
"""

from __future__ import annotations

from robocram.logic.errors import (
    PrologDomainError,
    PrologInstantiationError,
    PrologTypeError,
)
from robocram.logic.terms import Term, Var, deref
from robocram.logic.value import Value

__all__ = ["indicator_key", "indicator_pattern"]


def indicator_pattern(spec: Value, what: str) -> tuple[Value, Value]:
    """The name and arity of an indicator whose parts may be unbound.

    >>> indicator_pattern(Term("/", ("foo", 1)), "t")
    ('foo', 1)
    """
    spec = deref(spec)
    if type(spec) is not Term or spec[0] != "/" or len(spec[1]) != 2:
        raise PrologTypeError("predicate_indicator", spec, f"{what}: {spec!r} is not Name/Arity")
    name, arity = deref(spec[1][0]), deref(spec[1][1])
    if type(name) is not Var and type(name) is not str:
        raise PrologTypeError("predicate_indicator", spec, f"{what}: {name!r} is not an atom")
    if type(arity) is not Var:
        if type(arity) is not int:
            raise PrologTypeError("predicate_indicator", spec, f"{what}: {arity!r} is no arity")
        if arity < 0:
            raise PrologDomainError(
                "not_less_than_zero", arity, f"{what}: the arity {arity} is negative"
            )
    return name, arity


def indicator_key(spec: Value, what: str) -> tuple[str, int]:
    """The (name, arity) of a complete indicator; ISO errors name the offending part.

    >>> indicator_key(Term("/", ("foo", 2)), "abolish/1")
    ('foo', 2)
    """
    spec = deref(spec)
    if type(spec) is Var:
        raise PrologInstantiationError(f"{what}: the predicate indicator is unbound")
    if type(spec) is not Term or spec[0] != "/" or len(spec[1]) != 2:
        raise PrologTypeError("predicate_indicator", spec, f"{what}: {spec!r} is not Name/Arity")
    name, arity = deref(spec[1][0]), deref(spec[1][1])
    if type(name) is Var or type(arity) is Var:
        raise PrologInstantiationError(f"{what}: {spec!r} has an unbound name or arity")
    if type(name) is not str:
        raise PrologTypeError("atom", name, f"{what}: the name {name!r} is not an atom")
    if type(arity) is not int:
        raise PrologTypeError("integer", arity, f"{what}: the arity {arity!r} is not an integer")
    if arity < 0:
        raise PrologDomainError("not_less_than_zero", arity, f"{what}: the arity is negative")
    return name, arity

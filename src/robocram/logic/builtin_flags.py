"""Prolog flags: set_prolog_flag/2 and current_prolog_flag/2, per knowledge base.

`double_quotes` (codes, chars, atom, string) decides what "text" reads as, from the next
clause or query on; `unknown` (error, fail, warning) what a call to an undefined
predicate does; `occurs_check` (false, true, error) whether unification may make cyclic
terms, fails instead, or raises `occurs_check(Var, Term)` (see occurs.py).
"""

from __future__ import annotations

import sys
from collections.abc import Iterator

from robocram.logic.builtin_spec import Builtin, det, nondet
from robocram.logic.engine import Engine
from robocram.logic.errors import (
    PrologDomainError,
    PrologInstantiationError,
    PrologPermissionError,
    PrologTypeError,
)
from robocram.logic.terms import Term, Var, deref
from robocram.logic.value import Value

__all__ = ["BUILTINS", "default_flags"]

Args = tuple[Value, ...]

# flag -> the values it may be set to (empty: read-only)
_CHANGEABLE: dict[str, tuple[str, ...]] = {
    "double_quotes": ("codes", "chars", "atom", "string"),
    "unknown": ("error", "fail", "warning"),
    "occurs_check": ("false", "true", "error"),
    "debug": ("false", "true"),
}
# Boolean flags also take on/off, as in SWI-Prolog; they read back as true/false.
_BOOLEAN = {"on": "true", "off": "false"}
_READ_ONLY: dict[str, Value] = {
    "bounded": "false",
    "max_arity": "unbounded",
    "integer_rounding_function": "toward_zero",
    "char_conversion": "false",
    "max_integer_bits": 0,  # set by default_flags
}


def default_flags(max_integer_bits: int) -> dict[str, Value]:
    """A new knowledge base's flags (SWI-Prolog's defaults for the changeable ones)."""
    flags: dict[str, Value] = {"double_quotes": "string", "unknown": "error"}
    flags.update(occurs_check="false", debug="false")
    flags.update(_READ_ONLY, max_integer_bits=max_integer_bits)
    return flags


def _set_flag(m: Engine, a: Args) -> bool:
    flag, value = deref(a[0]), deref(a[1])
    if type(flag) is Var or type(value) is Var:
        raise PrologInstantiationError("set_prolog_flag/2: the flag and its value must be bound")
    if type(flag) is not str:
        raise PrologTypeError("atom", flag, f"set_prolog_flag/2: {flag!r} is not an atom")
    if flag in _READ_ONLY:
        raise PrologPermissionError(
            "modify", "flag", flag, f"set_prolog_flag/2: flag {flag} is read-only"
        )
    allowed = _CHANGEABLE.get(flag)
    if allowed is None:
        known = ", ".join(sorted([*_CHANGEABLE, *_READ_ONLY]))
        raise PrologDomainError(
            "prolog_flag", flag, f"set_prolog_flag/2: no flag {flag!r} (known: {known})"
        )
    if allowed == ("false", "true"):
        value = _BOOLEAN.get(value, value) if type(value) is str else value
        if value not in allowed:
            raise PrologTypeError("bool", deref(a[1]), f"set_prolog_flag/2: {flag} is a boolean")
    if value not in allowed:
        raise PrologDomainError(
            "flag_value",
            Term("+", (flag, value)),
            f"set_prolog_flag/2: {flag} may be {', '.join(allowed)}, not {value!r}",
        )
    with m.kb._lock:
        m.kb._flags[flag] = value
        m.kb.mark_changed(syntax=True)
    if flag == "occurs_check":
        m.occurs_check = value  # the running query unifies the new way from here on
    return True


def _current_flag(m: Engine, a: Args) -> Iterator[bool]:
    flag = deref(a[0])
    if type(flag) is not Var and type(flag) is not str:
        raise PrologTypeError("atom", flag, f"current_prolog_flag/2: {flag!r} is not an atom")
    for name, value in list(m.kb._flags.items()):
        mark = len(m.trail)
        if m.unify(a[0], name) and m.unify(a[1], value):
            yield True
        m.undo_to(mark)


def warn_unknown(name: str, arity: int) -> None:
    """What `unknown = warning` prints before failing."""
    sys.stderr.write(f"Warning: unknown procedure {name}/{arity}\n")


BUILTINS: tuple[Builtin, ...] = (
    det("set_prolog_flag", _set_flag, 2),
    nondet("current_prolog_flag", _current_flag, 2),
)

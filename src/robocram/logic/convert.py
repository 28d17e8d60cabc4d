"""Map Python values into engine terms and back.

`str` is an atom, `bool` the atoms true/false, `int`/`float` numbers, `list` a Prolog list,
`Term` a compound and `None` an opaque constant; any other object is opaque and unifies by
`==`. Answers map back the same way; a Prolog string comes back as `str`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import cast

from robocram.logic.acyclic import is_acyclic
from robocram.logic.terms import NIL, PString, Term, Var, make_term
from robocram.logic.value import Value

__all__ = ["NONE", "SelfContainingValue", "to_prolog", "to_python"]


class SelfContainingValue(ValueError):  # noqa: N818 - reads as what the value is
    """A Python list or Term that contains itself: no finite term stands for it."""

    def __init__(self) -> None:
        super().__init__(
            "a Python list or Term that contains itself; no finite term stands for it: "
            "pass a copy without the cycle"
        )


class _NoneBox:
    """Stands for Python `None` inside terms (a Var with ref None means unbound)."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "None"


NONE = _NoneBox()


def to_prolog(value: Value) -> Value:
    """Convert a Python value to an engine term.

    Values nested deeper than Python's stack allows are converted by `_to_prolog_deep`;
    a list that contains itself raises `SelfContainingValue` (no finite term stands for it).

    >>> to_prolog([1, "a"])
    [1,a]
    """
    try:
        return _to_prolog(value)
    except RecursionError:
        return _to_prolog_deep(value)


def _to_prolog(value: object) -> object:
    t = type(value)
    if t is str or t is int or t is float or t is Var or t is PString:
        return value
    if isinstance(value, list) and t is list:
        result: object = NIL
        for item in reversed(value):
            result = make_term((".", (_to_prolog(item), result)))
        return result
    if isinstance(value, Term) and t is Term:
        return make_term((value[0], tuple([_to_prolog(a) for a in value[1]])))
    return _to_prolog_leaf(value)


def _to_prolog_leaf(value: object) -> object:
    t = type(value)
    if t is bool:
        return "true" if value else "false"
    if value is None:
        return NONE
    if isinstance(value, str):
        return str(value)
    if isinstance(value, int) and not isinstance(value, bool):
        return int(value)
    if isinstance(value, float):
        return float(value)
    return value


def _to_prolog_deep(value: object) -> object:
    """`to_prolog` with an explicit stack, for a list or term of any depth."""
    out: list[object] = []
    open_ids: set[int] = set()  # lists and terms being converted: seeing one again is a cycle
    stack: list[tuple[bool, object]] = [(False, value)]
    while stack:
        built, v = stack.pop()
        items = _items(v)
        if items is None:
            out.append(_to_prolog(v))
        elif built:
            open_ids.discard(id(v))
            args = out[len(out) - len(items) :] if items else []
            del out[len(out) - len(items) :]
            out.append(_assembled_prolog(v, args))
        else:
            if id(v) in open_ids:
                raise SelfContainingValue()
            open_ids.add(id(v))
            stack.append((True, v))
            stack.extend((False, item) for item in reversed(items))
    return out[0]


def _items(value: object) -> Sequence[object] | None:
    """The items of a list or the arguments of a Term; ``None`` for anything else."""
    if type(value) is list:
        return cast("list[object]", value)
    if isinstance(value, Term) and type(value) is Term:
        return cast("tuple[object, ...]", value[1])
    return None


def _assembled_prolog(value: object, args: list[object]) -> object:
    """The term of ``value`` (a list or Term) from its converted items ``args``."""
    if isinstance(value, Term) and type(value) is Term:
        return make_term((value[0], tuple(args)))
    result: object = NIL
    for item in reversed(args):
        result = make_term((".", (item, result)))
    return result


def to_python(term: Value) -> Value:
    """Convert an engine term (following bindings) to a Python value.

    Terms nested deeper than Python's stack allows are converted by `_to_python_deep`.

    >>> to_python(to_prolog([1, [2, "x"]]))
    [1, [2, 'x']]
    """
    try:
        return _to_python(term)
    except RecursionError:
        if not is_acyclic(term):
            raise  # a cyclic term has no finite Python value
        return _to_python_deep(term)


def _to_python_deep(term: Value) -> Value:
    """`to_python` with an explicit stack, for an acyclic term of any depth."""
    out: list[Value] = []
    stack: list[tuple[bool, Value]] = [(False, term)]
    while stack:
        built, t = stack.pop()
        if built:
            n = len(t[1])
            args = out[len(out) - n :]
            del out[len(out) - n :]
            out.append(_assemble(t[0], args))
            continue
        while type(t) is Var and t.ref is not None:
            t = t.ref
        if type(t) is Term:
            stack.append((True, t))
            stack.extend((False, a) for a in reversed(t[1]))
        else:
            out.append(_to_python(t))
    return out[0]


def _assemble(name: str, args: list[Value]) -> Value:
    """A converted compound: `'.'(H, T)` with a Python list tail becomes a list."""
    if name == "." and len(args) == 2 and type(args[1]) is list:
        return [args[0], *args[1]]
    return Term(name, tuple(args))


def _to_python(term: Value) -> Value:
    while type(term) is Var:
        if term.ref is None:
            return term
        term = term.ref
    t = type(term)
    if t is Term:
        if term[0] == "." and len(term[1]) == 2:
            items = []
            saved: Value = term
            power = 64
            while type(term) is Term and term[0] == "." and len(term[1]) == 2:
                items.append(_to_python(term[1][0]))
                term = term[1][1]
                while type(term) is Var and term.ref is not None:
                    term = term.ref
                if term is saved:  # Brent's test: a cyclic list has no Python value
                    raise RecursionError("a cyclic list has no Python value")
                if len(items) == power:
                    saved = term
                    power <<= 1
            if term == NIL:
                return items
            tail = _to_python(term)
            for item in reversed(items):
                tail = Term(".", (item, tail))
            return tail
        return Term(term[0], tuple([_to_python(a) for a in term[1]]))
    if t is PString:
        return term.text
    if term is NONE:
        return None
    if term == NIL and t is str:
        return []
    return term

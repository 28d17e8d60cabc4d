"""Map Python values into engine terms and back.

`str` is an atom, `bool` the atoms true/false, `int`/`float` numbers, `list` a Prolog list,
`Term` a compound and `None` an opaque constant; any other object is opaque and unifies by
`==`. Answers map back the same way; a Prolog string comes back as `str`.
"""

from __future__ import annotations

from typing import Any

from robocram.logic.terms import NIL, PString, Term, Var, new_term

__all__ = ["NONE", "to_prolog", "to_python"]


class _NoneBox:
    """Stands for Python `None` inside terms (a Var with ref None means unbound)."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "None"


NONE = _NoneBox()


def to_prolog(value: Any) -> Any:
    """Convert a Python value to an engine term.

    >>> to_prolog([1, "a"])
    [1,a]
    """
    t = type(value)
    if t is str or t is int or t is float or t is Var or t is PString:
        return value
    if t is list:
        result: Any = NIL
        for item in reversed(value):
            result = new_term(Term, (".", (to_prolog(item), result)))
        return result
    if t is Term:
        return new_term(Term, (value[0], tuple([to_prolog(a) for a in value[1]])))
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


def to_python(term: Any) -> Any:
    """Convert an engine term (following bindings) to a Python value.

    >>> to_python(to_prolog([1, [2, "x"]]))
    [1, [2, 'x']]
    """
    while type(term) is Var:
        if term.ref is None:
            return term
        term = term.ref
    t = type(term)
    if t is Term:
        if term[0] == "." and len(term[1]) == 2:
            items = []
            while type(term) is Term and term[0] == "." and len(term[1]) == 2:
                items.append(to_python(term[1][0]))
                term = term[1][1]
                while type(term) is Var and term.ref is not None:
                    term = term.ref
            if term == NIL:
                return items
            tail = to_python(term)
            for item in reversed(items):
                tail = Term(".", (item, tail))
            return tail
        return Term(term[0], tuple([to_python(a) for a in term[1]]))
    if t is PString:
        return term.text
    if term is NONE:
        return None
    if term == NIL and t is str:
        return []
    return term

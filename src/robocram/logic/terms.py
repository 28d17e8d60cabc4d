"""Prolog terms as Python values: atoms are `str`, numbers `int`/`float`, compounds `Term`.

Variables are mutable `Var` cells (bound by pointing `ref` at a value); everything else in
a term is immutable. A Python object of any other type is an opaque constant that unifies
with `==`. Prolog double-quoted strings are `PString` inside the engine.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

__all__ = ["NIL", "PString", "Term", "Var", "deref", "make_list"]

NIL = "[]"


class Var:
    """An unbound logic variable; `ref` is None until the variable is bound.

    >>> v = Var(); v.ref is None
    True
    """

    __slots__ = ("ref",)

    def __init__(self) -> None:
        self.ref: Any = None

    def __repr__(self) -> str:
        return f"_G{id(self) % 100000}"


class Term(tuple[str, tuple[Any, ...]]):
    """An immutable compound term `name(args...)`.

    >>> t = Term("point", (1, 2)); t.name, t.args
    ('point', (1, 2))
    """

    __slots__ = ()

    def __new__(cls, name: str, args: Iterable[Any] = ()) -> Term:
        return tuple.__new__(cls, (name, tuple(args)))

    @property
    def name(self) -> str:
        """The functor name."""
        return self[0]

    @property
    def args(self) -> tuple[Any, ...]:
        """The arguments, in order."""
        return self[1]

    @property
    def arity(self) -> int:
        """The number of arguments."""
        return len(self[1])

    def __eq__(self, other: object) -> bool:
        return type(other) is Term and tuple.__eq__(self, other)

    def __ne__(self, other: object) -> bool:
        return not self.__eq__(other)

    __hash__ = tuple.__hash__

    def __repr__(self) -> str:
        from robocram.logic.writer import format_term

        return format_term(self, quoted=True)


class PString:
    """A Prolog string ("text"): distinct from the atom with the same characters."""

    __slots__ = ("text",)

    def __init__(self, text: str) -> None:
        self.text = text

    def __eq__(self, other: object) -> bool:
        return type(other) is PString and other.text == self.text

    def __hash__(self) -> int:
        return hash(("$string", self.text))

    def __repr__(self) -> str:
        return f"PString({self.text!r})"


def deref(t: Any) -> Any:
    """Follow variable bindings to the value (or the unbound variable) at the end."""
    while type(t) is Var:
        r = t.ref
        if r is None:
            return t
        t = r
    return t


new_term = tuple.__new__


def make_list(items: Iterable[Any], tail: Any = NIL) -> Any:
    """Build a Prolog list (`'.'/2` cells) from engine terms.

    >>> make_list([1, 2])
    [1,2]
    """
    result = tail
    for item in reversed(list(items)):
        result = new_term(Term, (".", (item, result)))
    return result

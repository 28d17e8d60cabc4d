"""Prolog terms as Python values: atoms are `str`, numbers `int`/`float`, compounds `Term`.

Variables are mutable `Var` cells (bound by pointing `ref` at a value); everything else in
a term is immutable. A Python object of any other type is an opaque constant that unifies
with `==`. Prolog double-quoted strings are `PString` inside the engine. Terms write
themselves as Prolog text (`format_term`), which `repr`, `write/1` and error messages use.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from robocram.logic.bigint import int_text
from robocram.logic.operators import OperatorTable
from robocram.logic.value import Value

__all__ = [
    "NIL",
    "PString",
    "Term",
    "Var",
    "deref",
    "format_term",
    "make_list",
    "make_term",
    "make_var",
    "quote_atom",
]

NIL = "[]"


class _VarType(type):
    """Var's metaclass: `Var()` makes an unbound variable (`ref` None).

    Var itself has no `__init__`, so :data:`make_var` (type's own call, bound to Var)
    allocates one without a Python frame; the caller then sets `ref`.
    """

    def __call__(cls) -> Var:
        v: Var = type.__call__(cls)
        v.ref = None
        return v


class Var(metaclass=_VarType):
    """An unbound logic variable; `ref` is None until the variable is bound.

    >>> v = Var(); v.ref is None
    True
    """

    __slots__ = ("ref",)
    ref: Value

    def __repr__(self) -> str:
        return f"_G{id(self) % 100000}"


class _TermType(type):
    """Term's metaclass: `Term(name, args)` makes a compound term.

    Term itself has no `__new__` (tuple's is used), so :data:`make_term` (type's own
    call, bound to Term) builds one from a `(name, args)` pair without a Python frame or
    the argument checks and copies of `tuple.__new__(Term, ...)`.
    """

    def __call__(cls, name: str, args: Iterable[Value] = ()) -> Term:
        t: Term = type.__call__(cls, (name, tuple(args)))
        return t


class Term(tuple[str, tuple[Value, ...]], metaclass=_TermType):
    """An immutable compound term `name(args...)`.

    >>> t = Term("point", (1, 2)); t.name, t.args
    ('point', (1, 2))
    """

    __slots__ = ()

    if TYPE_CHECKING:  # the signature the metaclass's call gives `Term(...)`

        def __new__(cls, name: str, args: Iterable[Value] = ()) -> Term: ...

    @property
    def name(self) -> str:
        """The functor name."""
        return self[0]

    @property
    def args(self) -> tuple[Value, ...]:
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


def deref(t: Value) -> Value:
    """Follow variable bindings to the value (or the unbound variable) at the end."""
    while type(t) is Var:
        r = t.ref
        if r is None:
            return t
        t = r
    return t


# A Term from a `(name, args)` pair, for hot paths: `make_term((name, args))`.
make_term = type.__call__.__get__(Term)
# A Var with `ref` not yet set, for hot paths: `v = make_var(); v.ref = None`.
make_var = type.__call__.__get__(Var)


def make_list(items: Iterable[Value], tail: Value = NIL) -> Value:
    """Build a Prolog list (`'.'/2` cells) from engine terms.

    >>> make_list([1, 2])
    [1,2]
    """
    result = tail
    for item in reversed(list(items)):
        result = make_term((".", (item, result)))
    return result


_OPS = OperatorTable()
_SOLO = frozenset(["[]", "!", ";", "{}", ","])
_SYMBOLS = frozenset("+-*/\\^<>=~:.?@#&$")


def quote_atom(name: str) -> str:
    """Quote an atom when reading it back would need quotes.

    >>> quote_atom("hello"), quote_atom("Hello world"), quote_atom("=..")
    ('hello', "'Hello world'", '=..')
    """
    if name and name[0].islower() and all(c.isalnum() or c == "_" for c in name):
        return name
    if name and all(c in _SYMBOLS for c in name) or name in _SOLO and name != ",":
        return name
    escaped = name.replace("\\", "\\\\").replace("'", "\\'").replace("\n", "\\n")
    return f"'{escaped}'"


def format_term(
    term: Value,
    quoted: bool = False,
    max_prec: int = 1200,
    *,
    ignore_ops: bool = False,
    numbervars: bool = False,
) -> str:
    """Render a term as text; `quoted` quotes atoms and strings so they read back.

    `ignore_ops` writes operators in functional notation; `numbervars` writes
    `'$VAR'(N)` as a variable name (A, B, ..., Z, A1, ...).

    >>> format_term(Term("+", (1, Term("*", (2, "x")))))
    '1+2*x'
    >>> format_term(Term("+", (1, Term("$VAR", (27,)))), ignore_ops=True, numbervars=True)
    '+(1,B1)'
    """
    return _write(term, (quoted, ignore_ops, numbervars), max_prec)


Style = tuple[bool, bool, bool]  # quoted, ignore_ops, numbervars


def _write(term: Value, style: Style, max_prec: int) -> str:
    while type(term) is Var and term.ref is not None:
        term = term.ref
    t = type(term)
    quoted = style[0]
    if t is str:
        return quote_atom(term) if quoted else term
    if t is int:
        return int_text(term)
    if t is float or t is Var:
        return repr(term)
    if t is PString:
        return '"' + term.text.replace('"', '\\"') + '"' if quoted else term.text
    if t is Term:
        return _compound(term, style, max_prec)
    return repr(term)


def _var_name(n: int) -> str:
    return chr(ord("A") + n % 26) + (str(n // 26) if n >= 26 else "")


def _compound(term: Term, style: Style, max_prec: int) -> str:
    name, args = term[0], term[1]
    quoted, ignore_ops, numbervars = style
    if name == "." and len(args) == 2:
        return _list(term, style)
    if numbervars and name == "$VAR" and len(args) == 1:
        n = args[0]
        while type(n) is Var and n.ref is not None:
            n = n.ref
        if type(n) is int and n >= 0:
            return _var_name(n)
    if ignore_ops:
        inner = ",".join(_write(a, style, 999) for a in args)
        return f"{quote_atom(name) if quoted else name}({inner})"
    if name == "{}" and len(args) == 1:
        return "{" + _write(args[0], style, 1200) + "}"
    if len(args) == 2 and name in _OPS.infix:
        prec, kind = _OPS.infix[name]
        lp = prec if kind == "yfx" else prec - 1
        rp = prec if kind == "xfy" else prec - 1
        left = _write(args[0], style, lp)
        right = _write(args[1], style, rp)
        op = quote_atom(name) if quoted and name != "," else name
        sep = " " if name[0].isalpha() or name in ("->", ":-", "*->", "-->") else ""
        text = f"{left}{sep}{op}{sep}{right}"
        return f"({text})" if prec > max_prec else text
    if (
        len(args) == 1
        and name in _OPS.prefix
        and name not in ("-", "+")
        or (len(args) == 1 and name in ("-", "+") and type(args[0]) not in (int, float))
    ):
        prec, kind = _OPS.prefix[name]
        ap = prec if kind == "fy" else prec - 1
        arg = _write(args[0], style, ap)
        op = quote_atom(name) if quoted else name
        sep = " " if name[0].isalpha() or (arg and arg[0] in _SYMBOLS) else ""
        text = f"{op}{sep}{arg}"
        return f"({text})" if prec > max_prec else text
    inner = ",".join(_write(a, style, 999) for a in args)
    return f"{quote_atom(name) if quoted else name}({inner})"


def _list(term: Value, style: Style) -> str:
    items: list[str] = []
    saved: Value = term
    power = 64
    while type(term) is Term and term[0] == "." and len(term[1]) == 2:
        items.append(_write(term[1][0], style, 999))
        term = term[1][1]
        while type(term) is Var and term.ref is not None:
            term = term.ref
        if term is saved:  # Brent's test; a cyclic compound ends the same way, in recursion
            raise RecursionError("a cyclic list cannot be written")
        if len(items) == power:
            saved = term
            power <<= 1
    if term == NIL and type(term) is str:
        return "[" + ",".join(items) + "]"
    return "[" + ",".join(items) + "|" + _write(term, style, 999) + "]"

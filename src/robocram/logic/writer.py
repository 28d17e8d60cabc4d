"""Write engine terms as Prolog text (for `format/2,3`, `write`, error messages and repr)."""

from __future__ import annotations

from typing import Any

from robocram.logic.operators import OperatorTable
from robocram.logic.terms import NIL, PString, Term, Var

__all__ = ["format_term", "quote_atom"]

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


def format_term(term: Any, quoted: bool = False, max_prec: int = 1200) -> str:
    """Render a term as text; `quoted` quotes atoms and strings so they read back.

    >>> format_term(Term("+", (1, Term("*", (2, "x")))))
    '1+2*x'
    """
    while type(term) is Var and term.ref is not None:
        term = term.ref
    t = type(term)
    if t is str:
        return quote_atom(term) if quoted else term
    if t is int or t is float:
        return repr(term)
    if t is Var:
        return repr(term)
    if t is PString:
        return '"' + term.text.replace('"', '\\"') + '"' if quoted else term.text
    if t is Term:
        return _compound(term, quoted, max_prec)
    return repr(term)


def _compound(term: Term, quoted: bool, max_prec: int) -> str:
    name, args = term[0], term[1]
    if name == "." and len(args) == 2:
        return _list(term, quoted)
    if name == "{}" and len(args) == 1:
        return "{" + format_term(args[0], quoted) + "}"
    if len(args) == 2 and name in _OPS.infix:
        prec, kind = _OPS.infix[name]
        lp = prec if kind == "yfx" else prec - 1
        rp = prec if kind == "xfy" else prec - 1
        left = format_term(args[0], quoted, lp)
        right = format_term(args[1], quoted, rp)
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
        arg = format_term(args[0], quoted, ap)
        op = quote_atom(name) if quoted else name
        sep = " " if name[0].isalpha() or (arg and arg[0] in _SYMBOLS) else ""
        text = f"{op}{sep}{arg}"
        return f"({text})" if prec > max_prec else text
    inner = ",".join(format_term(a, quoted, 999) for a in args)
    return f"{quote_atom(name) if quoted else name}({inner})"


def _list(term: Any, quoted: bool) -> str:
    items: list[str] = []
    while type(term) is Term and term[0] == "." and len(term[1]) == 2:
        items.append(format_term(term[1][0], quoted, 999))
        term = term[1][1]
        while type(term) is Var and term.ref is not None:
            term = term.ref
    if term == NIL and type(term) is str:
        return "[" + ",".join(items) + "]"
    return "[" + ",".join(items) + "|" + format_term(term, quoted, 999) + "]"

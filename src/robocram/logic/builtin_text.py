"""Characters, codes and numbers as text: char_code/2, atom_chars/2 and friends, sub_atom/5.

Errors follow ISO: an unbound argument where text is needed is an instantiation error, a
list element that is not a character is `type_error(character, E)`, a code outside
Unicode is `representation_error(character_code)`, and text that is not a number is
`syntax_error(illegal_number)`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator

from robocram.logic.bigint import int_text
from robocram.logic.builtin_spec import Builtin, det, nondet
from robocram.logic.builtin_terms import need_int
from robocram.logic.cycles import list_prefix
from robocram.logic.engine import Engine
from robocram.logic.errors import (
    PrologDomainError,
    PrologError,
    PrologInstantiationError,
    PrologSyntaxError,
    PrologTypeError,
)
from robocram.logic.lexer import tokenize
from robocram.logic.long_work import checked_list
from robocram.logic.terms import NIL, PString, Term, Var, deref
from robocram.logic.value import Value

__all__ = ["BUILTINS", "parse_number"]

Args = tuple[Value, ...]
_MAX_CODE = 0x10FFFF


def parse_number(text: str) -> int | float | None:
    """The number Prolog reads from `text` (leading layout allowed), or None.

    >>> parse_number(" 0x1F"), parse_number("-2.5e1"), parse_number("12a")
    (31, -25.0, None)
    """
    try:
        tokens = tokenize(text)
    except (PrologError, ValueError):
        return None
    sign = 1
    if tokens[0].kind == "atom" and tokens[0].value == "-" and len(tokens) == 3:
        if tokens[1].layout_before:
            return None
        sign, tokens = -1, tokens[1:]
    if len(tokens) != 2 or tokens[0].kind != "num" or tokens[1].layout_before:
        return None
    value: int | float = tokens[0].value
    return sign * value


def _representation(code: Value) -> PrologError:
    ball = Term("error", (Term("representation_error", ("character_code",)), "bad code"))
    return PrologError(f"{code!r} is not a Unicode character code", ball)


def char_of(x: Value, what: str) -> str:
    """A one-character atom from a list element (ISO errors otherwise)."""
    x = deref(x)
    if type(x) is Var:
        raise PrologInstantiationError(f"{what}: a list element is unbound")
    if type(x) is not str or len(x) != 1:
        raise PrologTypeError("character", x, f"{what}: {x!r} is not a one-character atom")
    return x


def char_of_code(x: Value, what: str) -> str:
    """The character of a code list element (ISO errors otherwise)."""
    code = need_int(x, what)
    if not 0 <= code <= _MAX_CODE:
        raise _representation(code)
    return chr(code)


def text_items(
    t: Value,
    what: str,
    item: Callable[[Value, str], str],
    check: Callable[[], None] | None = None,
) -> str | None:
    """The text of a char or code list; None when the list is partial (can't tell yet).

    `check` (the query's limit check) is called as a long list is read.
    """
    cells, t = list_prefix(t, what, check)
    out = [item(c, what) for c in cells]
    if type(t) is Var:
        return None
    if t != NIL or type(t) is not str:
        raise PrologTypeError("list", t, f"{what}: expected a list, got {t!r}")
    return "".join(out)


def _source_text(t: Value, what: str, number: bool) -> str | None:
    t = deref(t)
    if type(t) is Var:
        return None
    if number:
        if type(t) not in (int, float):
            raise PrologTypeError("number", t, f"{what}: {t!r} is not a number")
        return int_text(t) if type(t) is int else repr(t)
    if type(t) in (str, int, float):
        return t if type(t) is str else int_text(t) if type(t) is int else repr(t)
    if type(t) is PString:
        return t.text
    raise PrologTypeError("atom", t, f"{what}: {t!r} is not an atom")


def _conversion(name: str, codes: bool, result: str) -> Builtin:
    item = char_of_code if codes else char_of

    def run(m: Engine, a: Args) -> bool:
        text = _source_text(a[0], name, result == "number")
        listed = text_items(a[1], name, item, m.budget.check)
        if listed is None:
            if text is None:
                raise PrologInstantiationError(f"{name}: both arguments are unbound")
            chars = [ord(c) for c in text] if codes else list(text)
            return m.unify(a[1], checked_list(chars, m.budget))
        if result == "number":
            value = parse_number(listed)
            if value is None:
                raise PrologSyntaxError("illegal_number", 1, 1, listed)
            return m.unify(a[0], value)
        return m.unify(a[0], PString(listed) if result == "string" else listed)

    return det(name, run, 2)


def _char_code(m: Engine, a: Args) -> bool:
    c = deref(a[0])
    if type(c) is not Var:
        code = deref(a[1])
        if type(code) is not Var and type(code) is not int:  # ISO checks both arguments
            raise PrologTypeError("integer", code, f"char_code/2: {code!r} is not an integer")
        return m.unify(code, ord(char_of(c, "char_code/2")))
    code = deref(a[1])
    if type(code) is Var:
        raise PrologInstantiationError("char_code/2: both arguments are unbound")
    return m.unify(c, char_of_code(code, "char_code/2"))


def _sub_atom(m: Engine, a: Args) -> Iterator[bool]:
    atom = deref(a[0])
    if type(atom) is Var:
        raise PrologInstantiationError("sub_atom/5: the atom is unbound")
    if type(atom) is not str:
        raise PrologTypeError("atom", atom, f"sub_atom/5: {atom!r} is not an atom")
    n = len(atom)
    fixed = [_opt_len(a[i], "sub_atom/5") for i in (1, 2, 3)]
    sub = deref(a[4])
    if type(sub) is not Var and type(sub) is not str:
        raise PrologTypeError("atom", sub, f"sub_atom/5: {sub!r} is not an atom")
    for b, length in _spans(atom, n, fixed, sub):
        mark = len(m.trail)
        if (
            m.unify(a[1], b)
            and m.unify(a[2], length)
            and m.unify(a[3], n - b - length)
            and m.unify(a[4], atom[b : b + length])
        ):
            yield True
        m.undo_to(mark)


def _opt_len(t: Value, what: str) -> int | None:
    t = deref(t)
    if type(t) is Var:
        return None
    value = need_int(t, what)
    if value < 0:
        raise PrologDomainError("not_less_than_zero", value, f"{what}: {value} is negative")
    return value


def _spans(atom: str, n: int, fixed: list[int | None], sub: Value) -> Iterator[tuple[int, int]]:
    """(before, length) pairs consistent with the bound arguments, in ISO order."""
    before, length, after = fixed
    if type(sub) is str:
        length = len(sub)
        start = 0
        while (found := atom.find(sub, start)) >= 0:
            if before in (None, found) and after in (None, n - found - length):
                yield found, length
            start = found + 1
        return
    if before is not None and length is not None:
        spans: Iterable[tuple[int, int]] = [(before, length)]
    elif before is not None and after is not None:
        spans = [(before, n - before - after)]
    elif length is not None and after is not None:
        spans = [(n - length - after, length)]
    elif before is not None:
        spans = ((before, k) for k in range(n - before + 1))
    elif length is not None:
        spans = ((b, length) for b in range(n - length + 1))
    elif after is not None:
        spans = ((b, n - after - b) for b in range(n - after + 1))
    else:
        spans = ((b, k) for b in range(n + 1) for k in range(n - b + 1))
    for b, k in spans:
        if b >= 0 and k >= 0 and b + k <= n:
            yield b, k


BUILTINS: tuple[Builtin, ...] = (
    det("char_code", _char_code, 2),
    _conversion("atom_chars", False, "atom"),
    _conversion("atom_codes", True, "atom"),
    _conversion("string_chars", False, "string"),
    _conversion("string_codes", True, "string"),
    _conversion("number_chars", False, "number"),
    _conversion("number_codes", True, "number"),
    nondet("sub_atom", _sub_atom, 5),
)

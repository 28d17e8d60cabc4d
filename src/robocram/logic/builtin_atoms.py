"""Atom and string built-ins and `format/1,2,3`."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING

from robocram.logic.bigint import int_text
from robocram.logic.builtin_spec import Builtin, det, nondet
from robocram.logic.builtin_terms import list_items
from robocram.logic.builtin_text import char_of, char_of_code, parse_number
from robocram.logic.errors import (
    PrologDomainError,
    PrologError,
    PrologInstantiationError,
    PrologTypeError,
)
from robocram.logic.reader import read_query
from robocram.logic.terms import PString, Term, Var, deref, format_term, make_list
from robocram.logic.value import Value

if TYPE_CHECKING:
    from robocram.logic.engine import Engine

__all__ = ["format_text", "text_of"]

Args = tuple[Value, ...]


def text_of(t: Value, what: str) -> str:
    """The characters of an atomic term (atom, string, number)."""
    t = deref(t)
    if type(t) is str:
        return t
    if type(t) is PString:
        return t.text
    if type(t) is int:
        return int_text(t)
    if type(t) is float:
        return repr(t)
    if type(t) is Var:
        raise PrologInstantiationError(f"{what}: argument is unbound; bind it to an atom")
    raise PrologTypeError("atomic", t, f"{what}: {t!r} is not an atom, string or number")


def _char(x: Value) -> str:
    return char_of(x, "format ~s") if type(x) is str else char_of_code(x, "format ~s")


def _bound(t: Value) -> bool:
    return type(deref(t)) is not Var


def _atom_concat(m: Engine, a: Args) -> Iterator[bool]:
    if _bound(a[0]) and _bound(a[1]):
        if m.unify(a[2], text_of(a[0], "atom_concat/3") + text_of(a[1], "atom_concat/3")):
            yield True
        return
    whole = text_of(a[2], "atom_concat/3")
    for i in range(len(whole) + 1):
        mark = len(m.trail)
        if m.unify(a[0], whole[:i]) and m.unify(a[1], whole[i:]):
            yield True
        m.undo_to(mark)


def _atom_length(m: Engine, a: Args) -> bool:
    t = deref(a[0])
    if type(t) is Term:
        raise PrologTypeError("atom", t, f"atom_length/2: {t!r} is not an atom")
    text = text_of(t, "atom_length/2")
    n = deref(a[1])
    if type(n) is not Var:
        if type(n) is not int:
            raise PrologTypeError("integer", n, f"atom_length/2: {n!r} is not an integer")
        if n < 0:
            raise PrologDomainError("not_less_than_zero", n, f"atom_length/2: {n} < 0")
    return m.unify(n, len(text))


def _string_length(m: Engine, a: Args) -> bool:
    return m.unify(a[1], len(text_of(a[0], "string_length/2")))


def _atom_number(m: Engine, a: Args) -> bool:
    if _bound(a[0]):
        value = parse_number(text_of(a[0], "atom_number/2"))
        return value is not None and m.unify(a[1], value)
    return m.unify(a[0], text_of(a[1], "atom_number/2"))


def _atom_string(m: Engine, a: Args) -> bool:
    if _bound(a[0]):
        return m.unify(a[1], PString(text_of(a[0], "atom_string/2")))
    return m.unify(a[0], text_of(a[1], "atom_string/2"))


def _string_concat(m: Engine, a: Args) -> bool:
    return m.unify(
        a[2], PString(text_of(a[0], "string_concat/3") + text_of(a[1], "string_concat/3"))
    )


def _upcase(m: Engine, a: Args) -> bool:
    return m.unify(a[1], text_of(a[0], "upcase_atom/2").upper())


def _downcase(m: Engine, a: Args) -> bool:
    return m.unify(a[1], text_of(a[0], "downcase_atom/2").lower())


def _term_to_atom(m: Engine, a: Args) -> bool:
    if _bound(a[0]):
        return m.unify(a[1], format_term(a[0], quoted=True))
    term, _ = read_query(text_of(a[1], "term_to_atom/2"), m.kb._ops, m.kb._flags)
    return m.unify(a[0], term)


def _atomic_list_concat3(m: Engine, a: Args) -> Iterator[bool]:
    sep = text_of(a[1], "atomic_list_concat/3")
    items = deref(a[0])
    try:
        parts = [
            text_of(x, "atomic_list_concat/3") for x in list_items(items, "atomic_list_concat/3")
        ]
    except PrologInstantiationError:
        if not sep:
            raise
        pieces = text_of(a[2], "atomic_list_concat/3").split(sep)
        if m.unify(items, make_list(pieces)):
            yield True
        return
    if m.unify(a[2], sep.join(parts)):
        yield True


def _atomic_list_concat2(m: Engine, a: Args) -> bool:
    parts = [text_of(x, "atomic_list_concat/2") for x in list_items(a[0], "atomic_list_concat/2")]
    return m.unify(a[1], "".join(parts))


def _directive(text: str, i: int) -> tuple[str | None, str, int]:
    """Read `~[N]c` at text[i] == '~'; return (numeric argument, directive char, next index)."""
    j = i + 1
    while j < len(text) and (text[j].isdigit() or text[j] == "*"):
        j += 1
    if j >= len(text):
        raise PrologError(f"format: directive at the end of {text!r} is incomplete")
    return (text[i + 1 : j] or None), text[j], j + 1


def format_text(fmt: str, args: list[Value]) -> str:
    """Expand a format string (~w ~p ~q ~a ~d ~f ~e ~g ~s ~n ~c ~r ~t ~| ~+ ~i ~~).

    >>> format_text("~w has ~d items, ~2f kg~n", ["box", 3, 1.5])
    'box has 3 items, 1.50 kg\\n'
    """
    out: list[str] = []
    queue = list(args)
    i = 0

    def take(d: str) -> Value:
        if not queue:
            raise PrologError(f"format: not enough arguments for ~{d} in {fmt!r}")
        return deref(queue.pop(0))

    while i < len(fmt):
        c = fmt[i]
        if c != "~":
            out.append(c)
            i += 1
            continue
        num, d, i = _directive(fmt, i)
        out.append(_expand(d, num, take, fmt))
    if queue:
        raise PrologError(f"format: too many arguments for {fmt!r}")
    return "".join(out)


def _expand(d: str, num: str | None, take: Callable[[str], Value], fmt: str) -> str:
    if d in "wpa":
        return format_term(take(d))
    if d == "q":
        return format_term(take(d), quoted=True)
    if d == "d":
        value = take(d)
        if type(value) is not int:
            raise PrologTypeError("integer", value, f"format ~d: {value!r} is not an integer")
        if num and int(num) > 0:
            text = int_text(abs(value)).rjust(int(num) + 1, "0")
            return ("-" if value < 0 else "") + text[: -int(num)] + "." + text[-int(num) :]
        return int_text(value)
    if d in "feg":
        value = take(d)
        if type(value) not in (int, float):
            raise PrologTypeError("number", value, f"format ~{d}: {value!r} is not a number")
        return f"{float(value):.{int(num) if num else 6}{d}}"
    if d == "n":
        return "\n" * (int(num) if num else 1)
    if d == "c":
        return chr(take(d)) * (int(num) if num else 1)
    if d == "s":
        value = take(d)
        return (
            value.text
            if type(value) is PString
            else "".join(_char(deref(x)) for x in list_items(value, "~s"))
        )
    if d == "~":
        return "~"
    if d == "i":
        take(d)
        return ""
    if d in "t|+":
        return ""
    raise PrologError(f"format: unknown directive ~{d} in {fmt!r}")


def _format_args(t: Value) -> list[Value]:
    t = deref(t)
    if type(t) is Term and t[0] == "." or t == "[]":
        return list_items(t, "format")
    return [t]


def _emit(m: Engine, sink: Value, text: str) -> bool:
    sink = deref(sink)
    if type(sink) is Term and len(sink[1]) == 1 and sink[0] in ("atom", "string", "codes", "chars"):
        kind = sink[0]
        value: Value = text if kind == "atom" else PString(text)
        if kind == "codes":
            value = make_list([ord(c) for c in text])
        if kind == "chars":
            value = make_list(list(text))
        return m.unify(sink[1][0], value)
    if sink in ("user_output", "user_error"):
        (sys.stdout if sink == "user_output" else sys.stderr).write(text)
        return True
    raise PrologTypeError(
        "output_sink", sink, f"format/3: {sink!r} is not atom(A), string(S) or user_output"
    )


def _format(m: Engine, a: Args) -> bool:
    if len(a) == 3:
        return _emit(m, a[0], format_text(text_of(a[1], "format/3"), _format_args(a[2])))
    args = _format_args(a[1]) if len(a) == 2 else []
    sys.stdout.write(format_text(text_of(a[0], "format"), args))
    return True


BUILTINS: tuple[Builtin, ...] = (
    nondet("atom_concat", _atom_concat, 3),
    det("atom_length", _atom_length, 2),
    det("string_length", _string_length, 2),
    det("atom_number", _atom_number, 2),
    det("atom_string", _atom_string, 2),
    det("string_concat", _string_concat, 3),
    det("upcase_atom", _upcase, 2),
    det("downcase_atom", _downcase, 2),
    det("term_to_atom", _term_to_atom, 2),
    nondet("atomic_list_concat", _atomic_list_concat3, 3),
    det("atomic_list_concat", _atomic_list_concat2, 2),
    det("format", _format, 1, 2, 3),
)

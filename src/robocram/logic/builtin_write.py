"""Term output and reading terms from text: write/print/writeq/write_canonical/write_term,
nl, and read_term_from_atom/3, term_string/2.

Output goes to Python's `sys.stdout` (`user_output`) or `sys.stderr` (`user_error`), looked
up at each call so that redirecting them (pytest's capture, a GUI console) works.
"""

from __future__ import annotations

import sys
from typing import TextIO

from robocram.logic.builtin_spec import Builtin, det
from robocram.logic.builtin_terms import list_items
from robocram.logic.engine import DetFn, Engine
from robocram.logic.errors import (
    PrologDomainError,
    PrologExistenceError,
    PrologInstantiationError,
)
from robocram.logic.reader import read_query
from robocram.logic.terms import PString, Term, Var, deref, format_term
from robocram.logic.value import Value

__all__ = ["BUILTINS"]

Args = tuple[Value, ...]
_BOOLEAN_OPTIONS = ("quoted", "ignore_ops", "numbervars", "portray")


def _stream(t: Value) -> TextIO:
    t = deref(t)
    if type(t) is Var:
        raise PrologInstantiationError("output: the stream is unbound")
    if t == "user_output":
        return sys.stdout
    if t == "user_error":
        return sys.stderr
    raise PrologExistenceError(
        "stream", t, f"no output stream {t!r}; use user_output or user_error"
    )


def write_options(options: Value, what: str) -> dict[str, bool]:
    """The write_term/2 options as flags (ISO errors for bad or unknown ones)."""
    flags = dict.fromkeys(_BOOLEAN_OPTIONS, False)
    for option in list_items(options, what):
        option = deref(option)
        if type(option) is Var:
            raise PrologInstantiationError(f"{what}: an option is unbound")
        if type(option) is not Term or len(option[1]) != 1 or option[0] not in flags:
            raise PrologDomainError(
                "write_option",
                option,
                f"{what}: unknown option {option!r}; use {', '.join(_BOOLEAN_OPTIONS)}(Bool)",
            )
        value = deref(option[1][0])
        if value not in ("true", "false"):
            raise PrologDomainError("write_option", option, f"{what}: {option!r} needs true/false")
        flags[option[0]] = value == "true"
    return flags


def _text(t: Value, flags: dict[str, bool]) -> str:
    return format_term(
        t, flags["quoted"], ignore_ops=flags["ignore_ops"], numbervars=flags["numbervars"]
    )


def _writer(quoted: bool, ignore_ops: bool, numbervars: bool, newline: str = "") -> DetFn:
    flags = {"quoted": quoted, "ignore_ops": ignore_ops, "numbervars": numbervars}

    def run(m: Engine, a: Args) -> bool:
        out = sys.stdout if len(a) == 1 else _stream(a[0])
        out.write(_text(a[-1], flags) + newline)
        return True

    return run


def _write_term(m: Engine, a: Args) -> bool:
    out = sys.stdout if len(a) == 2 else _stream(a[0])
    out.write(_text(a[-2], write_options(a[-1], "write_term")))
    return True


def _nl(m: Engine, a: Args) -> bool:
    (sys.stdout if not a else _stream(a[0])).write("\n")
    return True


def _read_from(m: Engine, text: Value, what: str) -> Value:
    t = deref(text)
    if type(t) is Var:
        raise PrologInstantiationError(f"{what}: the text is unbound")
    source = t.text if type(t) is PString else t if type(t) is str else format_term(t)
    term, _ = read_query(source, m.kb._ops, m.kb._flags)
    return term


def _read_term_from_atom(m: Engine, a: Args) -> bool:
    return m.unify(a[1], _read_from(m, a[0], "read_term_from_atom/3"))


def _term_string(m: Engine, a: Args) -> bool:
    if type(deref(a[0])) is Var and type(deref(a[1])) is not Var:
        return m.unify(a[0], _read_from(m, a[1], "term_string/2"))
    return m.unify(a[1], PString(format_term(a[0], quoted=True)))


BUILTINS: tuple[Builtin, ...] = (
    det("write", _writer(False, False, True), 1, 2),
    det("print", _writer(True, False, True), 1, 2),
    det("writeln", _writer(False, False, True, "\n"), 1, 2),
    det("writeq", _writer(True, False, True), 1, 2),
    det("write_canonical", _writer(True, True, False), 1, 2),
    det("write_term", _write_term, 2, 3),
    det("nl", _nl, 0, 1),
    det("read_term_from_atom", _read_term_from_atom, 3),
    det("term_string", _term_string, 2),
)

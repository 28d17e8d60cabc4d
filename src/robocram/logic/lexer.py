"""Split Prolog text into tokens (atoms, variables, numbers, strings, punctuation, end)."""

from __future__ import annotations

import re
from dataclasses import dataclass

from robocram.logic.bigint import text_int
from robocram.logic.errors import PrologSyntaxError
from robocram.logic.value import Value

__all__ = ["Token", "line_col", "tokenize"]

SYMBOL_CHARS = frozenset("+-*/\\^<>=~:.?@#&$")
PUNCT = frozenset("()[]{},|")
_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", "a": "\a", "b": "\b", "f": "\f", "v": "\v"}
_ESCAPES.update({"0": "\0", "e": "\x1b", "s": " ", "\\": "\\", "'": "'", '"': '"', "`": "`"})


@dataclass(frozen=True, slots=True)
class Token:
    """One token: `kind` is atom, qatom, var, num, str, bq, punct, end or eof."""

    kind: str
    value: Value
    pos: int
    layout_before: bool


def line_col(text: str, pos: int) -> tuple[int, int]:
    """Return the 1-based line and column of offset `pos`."""
    line = text.count("\n", 0, pos) + 1
    return line, pos - (text.rfind("\n", 0, pos) + 1) + 1


def syntax_error(text: str, pos: int, reason: str) -> PrologSyntaxError:
    """Build a syntax error naming the line, column and the text at `pos`."""
    line, col = line_col(text, pos)
    end = text.find("\n", pos)
    snippet = text[pos : end if end >= 0 else len(text)][:40] or "<end of text>"
    return PrologSyntaxError(reason, line, col, snippet)


# layout: white space (``str.isspace``, as ``\s`` matches), ``%`` line comments and
# ``/* */`` block comments; one match skips a whole run of them
_LAYOUT = re.compile(r"(?:\s+|%[^\n]*\n?|/\*.*?\*/)*", re.DOTALL)


def _skip_layout(text: str, i: int) -> int:
    found = _LAYOUT.match(text, i)
    end = found.end() if found is not None else i  # (`*` always matches, if only nothing)
    if text.startswith("/*", end):  # a block comment the match could not close
        raise syntax_error(text, end, "unterminated block comment")
    return end


def _read_quoted(text: str, i: int, quote: str) -> tuple[str, int]:
    """Read a quoted item starting after the opening quote; return (content, next index)."""
    out: list[str] = []
    n = len(text)
    start = i - 1
    while True:
        if i >= n:
            raise syntax_error(text, start, f"unterminated quoted {quote}")
        c = text[i]
        if c == quote:
            if i + 1 < n and text[i + 1] == quote:
                out.append(quote)
                i += 2
                continue
            return "".join(out), i + 1
        if c == "\\":
            ch, i = _read_escape(text, i + 1)
            out.append(ch)
            continue
        out.append(c)
        i += 1


def _read_escape(text: str, i: int) -> tuple[str, int]:
    if i >= len(text):
        raise syntax_error(text, i - 1, "unterminated escape")
    c = text[i]
    if c == "\n":
        return "", i + 1
    if c in _ESCAPES and not (c == "0" and i + 1 < len(text) and text[i + 1].isdigit()):
        return _ESCAPES[c], i + 1
    if c == "x" or c.isdigit():
        j = i + 1 if c == "x" else i
        k = j
        while k < len(text) and text[k] in "0123456789abcdefABCDEF":
            k += 1
        digits = text[j:k]
        if not digits:
            raise syntax_error(text, i - 1, "bad \\x escape")
        code = int(digits, 16 if c == "x" else 8)
        if k < len(text) and text[k] == "\\":
            k += 1
        return chr(code), k
    raise syntax_error(text, i - 1, f"unknown escape \\{c}")


def _read_number(text: str, i: int) -> tuple[int | float, int]:
    n = len(text)
    if text.startswith("0'", i):
        j = i + 2
        if j < n and text[j] == "\\":
            ch, k = _read_escape(text, j + 1)
            return ord(ch), k
        if text.startswith("''", j):
            return ord("'"), j + 2
        if j < n:
            return ord(text[j]), j + 1
    for prefix, base, digits in (
        ("0x", 16, "0123456789abcdefABCDEF"),
        ("0o", 8, "01234567"),
        ("0b", 2, "01"),
    ):
        if text.startswith(prefix, i) and i + 2 < n and text[i + 2] in digits:
            j = i + 2
            while j < n and text[j] in digits:
                j += 1
            return int(text[i + 2 : j], base), j
    j = i
    while j < n and (text[j].isdigit() or (text[j] == "_" and j + 1 < n and text[j + 1].isdigit())):
        j += 1
    is_float = False
    if j + 1 < n and text[j] == "." and text[j + 1].isdigit():
        is_float = True
        j += 1
        while j < n and text[j].isdigit():
            j += 1
    if j < n and text[j] in "eE":
        k = j + 1
        if k < n and text[k] in "+-":
            k += 1
        if k < n and text[k].isdigit():
            is_float = True
            j = k
            while j < n and text[j].isdigit():
                j += 1
    literal = text[i:j].replace("_", "")
    return (float(literal) if is_float else text_int(literal)), j


def tokenize(text: str) -> list[Token]:
    """Tokenize a whole text; raises PrologSyntaxError with the position of bad input."""
    tokens: list[Token] = []
    n = len(text)
    i = 0
    while True:
        j = _skip_layout(text, i)
        layout = j > i or i == 0
        i = j
        if i >= n:
            tokens.append(Token("eof", None, i, layout))
            return tokens
        c = text[i]
        start = i
        if c.isdigit():
            value, i = _read_number(text, i)
            tokens.append(Token("num", value, start, layout))
        elif c == "_" or c.isupper():
            while i < n and (text[i].isalnum() or text[i] == "_"):
                i += 1
            tokens.append(Token("var", text[start:i], start, layout))
        elif c.isalpha():
            while i < n and (text[i].isalnum() or text[i] == "_"):
                i += 1
            tokens.append(Token("atom", text[start:i], start, layout))
        elif c == "'":
            quoted, i = _read_quoted(text, i + 1, "'")
            tokens.append(Token("qatom", quoted, start, layout))
        elif c == '"':
            quoted, i = _read_quoted(text, i + 1, '"')
            tokens.append(Token("str", quoted, start, layout))
        elif c == "`":
            quoted, i = _read_quoted(text, i + 1, "`")
            tokens.append(Token("bq", quoted, start, layout))
        elif c == "." and (i + 1 >= n or text[i + 1].isspace() or text[i + 1] == "%"):
            tokens.append(Token("end", ".", start, layout))
            i += 1
        elif c in PUNCT:
            tokens.append(Token("punct", c, start, layout))
            i += 1
        elif c in "!;":
            tokens.append(Token("atom", c, start, layout))
            i += 1
        elif c in SYMBOL_CHARS:
            while i < n and text[i] in SYMBOL_CHARS:
                i += 1
            tokens.append(Token("atom", text[start:i], start, layout))
        else:
            raise syntax_error(text, i, f"unexpected character {c!r}")

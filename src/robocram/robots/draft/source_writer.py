"""Render Python values and calls as source text the way ``ruff format`` lays them out.

A call, tuple or dict goes on one line if it fits in :data:`WIDTH`; else a call's
arguments go on one indented line if they fit; else one item per line with a trailing
comma. Comments above an item force the last layout. Only what a drafted description
needs is supported.
"""

from __future__ import annotations

import textwrap
from collections.abc import Sequence
from dataclasses import dataclass, field

WIDTH = 100  # the project's line length
INDENT = "    "


@dataclass(frozen=True)
class Code:
    """Source text used as is (a name, an expression)."""

    text: str


@dataclass(frozen=True)
class Item:
    """One argument, dict entry or element: ``key`` (None for positional) and comments."""

    key: str | None
    value: object
    comments: tuple[str, ...] = ()
    dict_key: bool = False  # render ``"key": value`` instead of ``key=value``


@dataclass(frozen=True)
class Call:
    """A call (``opener`` "name(") or a literal collection ("(", "[", "{")."""

    opener: str
    items: Sequence[Item] = field(default_factory=tuple)
    closer: str = ")"
    one_tuple: bool = False  # a one-element tuple needs its trailing comma


def call(function: str, /, *args: object, **kwargs: object) -> Call:
    """``name(args..., key=value...)``; ``Item`` values keep their comments."""
    items = [a if isinstance(a, Item) else Item(None, a) for a in args]
    items += [v if isinstance(v, Item) else Item(k, v) for k, v in kwargs.items()]
    return Call(f"{function}(", items)


def _literal(value: object) -> object:
    if isinstance(value, tuple):
        return Call("(", [Item(None, v) for v in value], ")", one_tuple=len(value) == 1)
    if isinstance(value, dict):
        return Call("{", [Item(quoted(k), v, dict_key=True) for k, v in value.items()], "}")
    return value


def _flat(value: object) -> str:
    value = _literal(value)
    if isinstance(value, Code):
        return value.text
    if isinstance(value, Call):
        body = ", ".join(_flat_item(i) for i in value.items)
        return f"{value.opener}{body}{',' if value.one_tuple else ''}{value.closer}"
    if isinstance(value, float):
        return repr(round(value, 6))
    if isinstance(value, str):
        return quoted(value)
    return repr(value)


def quoted(text: str) -> str:
    """``text`` as a double-quoted Python string literal (ruff format's quotes); a name
    with a newline or a quote in it stays one string the draft loads back."""
    return '"' + "".join(_escaped(c) for c in text) + '"'


def _escaped(c: str) -> str:
    if c == "\\":
        return "\\\\"
    if c == '"':
        return '\\"'
    return c if c.isprintable() else repr(c)[1:-1]  # \n, \t, \x00, \u2028, ...


def _flat_item(item: Item) -> str:
    if item.key is None:
        return _flat(item.value)
    return (
        f"{item.key}: {_flat(item.value)}" if item.dict_key else f"{item.key}={_flat(item.value)}"
    )


def _has_comments(value: object) -> bool:
    value = _literal(value)
    if not isinstance(value, Call):
        return False
    return any(i.comments or _has_comments(i.value) for i in value.items)


def comment_lines(text: str, indent: str) -> list[str]:
    """``text`` as ``#`` comment lines at ``indent``, wrapped to the line length."""
    width = WIDTH - len(indent) - 2
    lines = textwrap.wrap(text, width=width, subsequent_indent="  ") or [""]
    return [f"{indent}# {line}" for line in lines]


def render(value: object, indent: str = "", lead: int = 0, trail: int = 0) -> str:
    """``value`` as source starting after ``lead`` characters, followed by ``trail`` more."""
    value = _literal(value)
    flat = _flat(value)
    if not isinstance(value, Call) or (
        len(indent) + lead + len(flat) + trail <= WIDTH and not _has_comments(value)
    ):
        return flat
    inner = indent + INDENT
    body = ", ".join(_flat_item(i) for i in value.items)
    is_call = len(value.opener) > 1  # literals explode one item per line instead
    fits = is_call and len(inner) + len(body) <= WIDTH
    if fits and not _has_comments(value) and value.items:
        return f"{value.opener}\n{inner}{body}\n{indent}{value.closer}"
    lines = [value.opener]
    for item in value.items:
        for comment in item.comments:
            lines += comment_lines(comment, inner)
        head = "" if item.key is None else (f"{item.key}: " if item.dict_key else f"{item.key}=")
        lines.append(f"{inner}{head}{render(item.value, inner, len(head), 1)},")
    lines.append(f"{indent}{value.closer}")
    return "\n".join(lines)

"""A name from outside Prolog (a link, a joint, an object type) as the text of an atom.

Facts written as text from such names must read back as exactly those names: a link
named ``X`` must not become a variable, nor ``t). :- retractall(...)`` a directive.
:func:`name_atom` leaves plain lower-case identifiers bare and quotes everything else,
escaping every character the reader would not take back literally. Every fact written
as text from a name goes through it.
"""

from __future__ import annotations

import re

from robocram.logic.usage_errors import LogicUsageError

__all__ = ["name_atom"]

_PLAIN = re.compile(r"[a-z][A-Za-z0-9_]*")
_NAMED_ESCAPES = {"\\": "\\\\", "'": "\\'", "\n": "\\n", "\t": "\\t", "\r": "\\r"}


def name_atom(name: str) -> str:
    """Write ``name`` as an atom that the reader reads back as exactly ``name``.

    >>> name_atom("table_top"), name_atom("Table_top"), name_atom("it's")
    ('table_top', "'Table_top'", "'it\\\\'s'")
    >>> name_atom("[]"), name_atom("a\\nb")
    ("'[]'", "'a\\\\nb'")
    """
    if not isinstance(name, str):
        raise LogicUsageError(f"a name written into a fact must be a str, not {name!r}")
    if _PLAIN.fullmatch(name):
        return name
    return "'" + "".join(_escaped(c) for c in name) + "'"


def _escaped(c: str) -> str:
    named = _NAMED_ESCAPES.get(c)
    if named is not None:
        return named
    if c.isprintable():
        return c
    return f"\\x{ord(c):x}\\"

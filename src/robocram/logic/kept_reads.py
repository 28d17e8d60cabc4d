"""Texts read in the standard syntax, kept on disk: a new process reads no text twice.

Reading Prolog text is slow (the motion groundings a projection consults, 44 clauses,
take ~7 ms), and a script's first plan reads the same texts every process. The clause
terms of a text without directives, read with the standard operators and flags, are
kept under the user's cache folder (``$ROBOCRAM_CACHE_DIR``, else
``$XDG_CACHE_HOME/robocram``, else ``~/.cache/robocram``, as the other disk caches), in
``prolog-terms``, named by a hash of the text and of the reader's source (the modules
that decide what a text reads to). A term is stored as marshalled plain values (a
compound as ``(name, args)``, a variable as ``[number]``, a string as ``(text,)``), so
reading it back runs no code but ours. A file starts with a SHA-256 of the rest, which
holds the full key: a damaged, cut or foreign file is read again from the text and
replaced, never used. Files are written under a temporary name and renamed into place,
so processes writing one entry at once each leave a whole file; a cache that cannot be
written only makes reading cost what it did.
"""

from __future__ import annotations

import functools
import hashlib
import importlib
import marshal
from collections.abc import Sequence
from pathlib import Path

from robocram.logic.sealed_files import cache_folder, read_sealed, write_sealed
from robocram.logic.terms import PString, Term, Var, make_var
from robocram.logic.value import Value

__all__ = ["keep_terms", "kept_terms"]

_KIND = "prolog-terms"
_FORMAT = "1"
# the modules whose code decides what a text reads to in the standard syntax
READ_BY = (
    __name__,
    "robocram.logic.reader",
    "robocram.logic.lexer",
    "robocram.logic.operators",
    "robocram.logic.builtin_flags",
    "robocram.logic.terms",
)
# a term as plain values (see the module docstring)
Encoded = str | int | float | tuple["Encoded", ...] | list[int]


class _NotKept(Exception):  # noqa: N818 - reads as what happened
    """A term plain values cannot hold, or a kept one not of this module's making: it is
    not kept, or not used (never seen outside this module)."""


def kept_terms(text: str) -> list[Value] | None:
    """The clause terms kept for ``text``, or None (none kept, or not to be trusted)."""
    key = _key(text)
    body = read_sealed(_path(key))
    if body is None:
        return None
    try:
        stored = marshal.loads(body)
        if not (isinstance(stored, tuple) and len(stored) == 2 and stored[0] == key):
            return None
        return [_decoded(term, []) for term in stored[1]]
    except (_NotKept, ValueError, EOFError, TypeError, IndexError, RecursionError):
        return None


def keep_terms(text: str, terms: Sequence[Value]) -> None:
    """Keep the clause terms ``text`` read to (a text without directives, read in the
    standard syntax); terms that plain values cannot hold are not kept."""
    key = _key(text)
    try:
        body = marshal.dumps((key, tuple(_encoded(term, {}) for term in terms)))
    except (_NotKept, ValueError, RecursionError):
        return
    write_sealed(_path(key), body)


def _encoded(term: Value, numbers: dict[Var, int]) -> Encoded:
    """``term`` as plain values; each variable of a clause numbered in ``numbers``."""
    kind = type(term)
    if kind is str or kind is int or kind is float:
        return term
    if isinstance(term, Term) and kind is Term:
        return (term[0], tuple(_encoded(a, numbers) for a in term[1]))
    if isinstance(term, Var):
        if term.ref is not None:
            raise _NotKept("a bound variable in a read term")
        return [numbers.setdefault(term, len(numbers))]
    if isinstance(term, PString):
        return (term.text,)
    raise _NotKept(f"a read term holds a {kind.__name__}")


def _decoded(value: object, variables: list[Var]) -> Value:
    """The term :func:`_encoded` gave; ``variables`` collects the clause's variables.
    Marshal gives exact types, as :func:`_encoded` wrote them: a tuple here is a compound
    or a string, a list a variable. Tested by exact type, most common first: 40 % faster
    than ``isinstance`` (a process's first plan decodes ~900 clauses)."""
    if type(value) is str or type(value) is int or type(value) is float:
        return value
    if type(value) is tuple:
        if len(value) == 2:
            name, args = value
            if type(name) is not str or type(args) is not tuple:
                raise _NotKept("a compound's name is no atom or its arguments no tuple")
            return Term(name, tuple([_decoded(a, variables) for a in args]))
        if len(value) == 1 and type(value[0]) is str:
            return PString(value[0])
    elif type(value) is list and len(value) == 1 and type(value[0]) is int:
        number: int = value[0]
        if not 0 <= number <= len(variables):  # numbered in order of first appearance
            raise _NotKept("a variable out of order")
        if number == len(variables):
            fresh = make_var()
            fresh.ref = None
            variables.append(fresh)
        return variables[number]
    raise _NotKept(f"a kept term holds a {type(value).__name__}")


def _key(text: str) -> str:
    code = "\n".join(_source_digest(module) for module in READ_BY)
    return hashlib.sha256(f"{_FORMAT}\n{code}\n{text}".encode("utf-8", "surrogatepass")).hexdigest()


@functools.cache
def _source_digest(module: str) -> str:
    """A hash of ``module``'s source (the code that reads texts)."""
    path = getattr(importlib.import_module(module), "__file__", None)
    return module if path is None else hashlib.sha256(Path(path).read_bytes()).hexdigest()


def _path(key: str) -> Path:
    return cache_folder(_KIND) / f"{key[:32]}.terms"

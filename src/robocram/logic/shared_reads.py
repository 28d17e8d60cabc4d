"""Texts read with the standard syntax, shared by every knowledge base of a process.

A projection consults the same texts into each new world's knowledge base (the motion
groundings, the grasp facts, the process module interface) and asks the same queries of
it; reading and compiling them was most of a new world's Prolog set-up. What a text
reads to depends only on the operators and flags, so while a knowledge base still has the
standard ones (it never ran ``op/3`` or ``set_prolog_flag/2``) it takes what another one
read: a text's clause templates (each knowledge base makes its own :class:`Clause` of
them: a clause's generated code and counts are its own) and a query's template. Only
texts without directives are kept: a directive may change how the clauses after it read.
Templates are never changed (a query or a call builds fresh terms from them).
"""

from __future__ import annotations

from robocram.logic.clause import Clause
from robocram.logic.keys import pred_key
from robocram.logic.lru import LRUCache
from robocram.logic.value import Value

__all__ = ["STANDARD_SYNTAX", "SharedReads"]

KEPT_TEXTS = 64  # distinct consulted texts kept (a projection consults about six)
KEPT_QUERIES = 1024  # distinct query texts kept (as many as a knowledge base keeps)
Compiled = list[tuple[tuple[str, int], Clause]]
QueryTemplate = tuple[Value, dict[str, int], int]  # template, slot per name, slots
# per clause: its name and arity, head and body templates, variable count, source term
_Parts = tuple[str, int, tuple[Value, ...], tuple[Value, ...], int, Value]


class SharedReads:
    """The clause templates of texts and the templates of queries, read in standard syntax."""

    def __init__(self, texts: int = KEPT_TEXTS, queries: int = KEPT_QUERIES) -> None:
        self._texts: LRUCache[str, tuple[_Parts, ...]] = LRUCache(texts)
        self._queries: LRUCache[str, QueryTemplate] = LRUCache(queries)

    def clauses(self, text: str, group: str) -> Compiled | None:
        """New clauses of group ``group`` from the templates ``text`` read to, if kept."""
        parts = self._texts.get(text)
        if parts is None:
            return None
        return [
            (pred_key(name, arity), Clause(head, body, nvars, group, source, name))
            for name, arity, head, body, nvars, source in parts
        ]

    def keep_clauses(self, text: str, compiled: Compiled) -> None:
        """Keep the templates of ``compiled``, read from ``text`` (no directives in it)."""
        self._texts.put(
            text,
            tuple(
                (c.name, len(c.head), c.head, c.body_rev, c.nvars, c.source) for _, c in compiled
            ),
        )

    def query(self, text: str) -> QueryTemplate | None:
        """The template query ``text`` compiled to, if kept."""
        return self._queries.get(text)

    def keep_query(self, text: str, template: QueryTemplate) -> None:
        """Keep the template of query ``text``."""
        self._queries.put(text, template)


STANDARD_SYNTAX = SharedReads()  # the process's: a memo of pure functions of the text

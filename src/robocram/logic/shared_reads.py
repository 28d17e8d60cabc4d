"""Texts read with the standard syntax, shared by every knowledge base of a process.

A projection consults the same texts into each new world's knowledge base (the motion
groundings, the grasp facts, the process module interface); reading them is most of a
consult. What a text reads to depends only on the operators and flags, so while a
knowledge base still has the standard ones (it never ran ``op/3`` or
``set_prolog_flag/2``) it takes the terms another one read. Only texts without
directives are kept: a directive may change how the clauses after it read. The terms are
never bound or changed (a clause is compiled from a copy), so sharing them is safe.
"""

from __future__ import annotations

from robocram.logic.lru import LRUCache
from robocram.logic.value import Value

__all__ = ["SharedReads"]

KEPT_TEXTS = 64  # distinct texts kept (a projection consults about six)


class SharedReads:
    """The clause terms of texts read with the standard operators and flags."""

    def __init__(self, size: int = KEPT_TEXTS) -> None:
        self._terms: LRUCache[str, tuple[Value, ...]] = LRUCache(size)

    def get(self, text: str) -> tuple[Value, ...] | None:
        """The terms ``text`` read to, if kept."""
        return self._terms.get(text)

    def put(self, text: str, terms: tuple[Value, ...]) -> None:
        """Keep the terms of ``text`` (a text without directives, read in standard syntax)."""
        self._terms.put(text, terms)


STANDARD_SYNTAX = SharedReads()  # the process's: a memo of a pure function of the text

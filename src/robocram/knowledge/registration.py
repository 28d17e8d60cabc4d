"""Register the Python implementations of a source's predicates, exactly as the table lists.

The world and the grasp model implement their predicates in Python; they hand
:func:`register_predicates` one function per ``name/arity`` and it registers each with
the table's name and arity. An implementation the table does not list, or a table row
left without one, fails at once with both named, so the table and the code never drift.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from typing import Any, Protocol

from robocram.knowledge.errors import ImplementationMismatch
from robocram.knowledge.predicate import Source
from robocram.knowledge.predicate_table import predicates_of

Solutions = Iterator[tuple[Any, ...] | None]
Implementation = Callable[..., Solutions]


class PredicateSink(Protocol):
    """What registration needs of a knowledge base."""

    def add_predicate(self, name: str, arity: int, fn: Implementation) -> None:
        """Register ``fn`` as ``name/arity``."""


def register_predicates(
    kb: PredicateSink, source: Source, implementations: Mapping[str, Implementation]
) -> None:
    """Register ``implementations`` (by ``name/arity``) of every ``source`` predicate."""
    rows = predicates_of(source)
    wanted = {p.indicator for p in rows}
    missing = sorted(wanted - set(implementations))
    unknown = sorted(set(implementations) - wanted)
    if missing or unknown:
        raise ImplementationMismatch(source.value, missing, unknown)
    for p in rows:
        kb.add_predicate(p.name, p.arity, implementations[p.indicator])

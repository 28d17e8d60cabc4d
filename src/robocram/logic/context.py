"""The current knowledge base: a context variable set by `with using_kb(kb):`."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

from robocram.logic.errors import PrologError
from robocram.logic.knowledge_base import KnowledgeBase
from robocram.logic.usage_errors import LogicUsageError

__all__ = ["current_kb", "using_kb"]

_CURRENT: ContextVar[KnowledgeBase | None] = ContextVar("robocram_current_kb", default=None)


def current_kb() -> KnowledgeBase:
    """Return the knowledge base bound by the innermost `using_kb` block.

    >>> kb = KnowledgeBase()
    >>> with using_kb(kb):
    ...     current_kb() is kb
    True
    """
    kb = _CURRENT.get()
    if kb is None:
        raise PrologError("no current knowledge base; wrap the code in `with using_kb(kb):`")
    return kb


@contextmanager
def using_kb(kb: KnowledgeBase) -> Iterator[KnowledgeBase]:
    """Make `kb` the current knowledge base inside the block (per thread / task)."""
    if not isinstance(kb, KnowledgeBase):
        raise LogicUsageError(f"using_kb expects a KnowledgeBase, got {type(kb).__name__}")
    token = _CURRENT.set(kb)
    try:
        yield kb
    finally:
        _CURRENT.reset(token)

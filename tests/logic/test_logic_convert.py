"""Python values into queries: any depth converts, a self-containing list is typed (issue 24).

Before: a list nested 100,000 deep raised a raw ``RecursionError`` from ``to_prolog``.
"""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase, PrologResourceError


def _nested(depth: int) -> list[object]:
    deep: list[object] = []
    for _ in range(depth):
        deep = [deep]
    return deep


def test_a_list_nested_100k_deep_goes_into_a_query() -> None:
    kb = KnowledgeBase()
    assert kb.first("Y = [A], A = [B], length(Y, N)", Y=_nested(100_000))["N"] == 1  # type: ignore[index]
    assert kb.holds("Y == Z", Y=_nested(100_000), Z=_nested(100_000))
    assert not kb.holds("Y == Z", Y=_nested(100_000), Z=_nested(99_999))


def test_a_list_that_contains_itself_is_a_resource_error_naming_the_fix() -> None:
    cyclic: list[object] = [1]
    cyclic.append(cyclic)
    culprit = "binding Y= is a Python list or Term that contains itself; .* pass a copy"
    with pytest.raises(PrologResourceError, match=culprit):
        KnowledgeBase().first("X = Y", Y=cyclic)


def test_a_shared_deep_sublist_is_not_taken_for_a_cycle() -> None:
    shared = _nested(50_000)
    assert KnowledgeBase().holds("Y = [A, B], A == B", Y=[shared, shared])

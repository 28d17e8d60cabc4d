"""GC pacing is opt-in (``with fast_queries():``) and leaves a host's own tuning alone."""

from __future__ import annotations

import gc
from collections.abc import Iterator

import pytest

from robocram.logic import KnowledgeBase, PrologTypeError, fast_queries
from robocram.logic.gc_pacing import QUERY_GEN0_THRESHOLD

HOST = (12_345, 11, 12)  # a host application's own thresholds


@pytest.fixture
def host_thresholds() -> Iterator[None]:
    before = gc.get_threshold()
    gc.set_threshold(*HOST)
    try:
        yield
    finally:
        gc.set_threshold(*before)


def _kb(seen: list[int]) -> KnowledgeBase:
    kb = KnowledgeBase()

    @kb.predicate("gen0", 1)
    def gen0(x: object) -> object:
        seen.append(gc.get_threshold()[0])
        yield None

    kb.consult("p(1). p(2). p(3).\nq(X) :- p(X), gen0(_).")
    return kb


def test_queries_leave_the_collector_alone_by_default(host_thresholds: None) -> None:
    seen: list[int] = []
    assert _kb(seen).holds("findall(X, q(X), [1, 2, 3])")
    assert seen == [HOST[0]] * 3
    assert gc.get_threshold() == HOST


def test_opted_in_queries_pace_and_restore_the_hosts_thresholds(host_thresholds: None) -> None:
    seen: list[int] = []
    kb = _kb(seen)
    with fast_queries():
        answers = kb.query("q(X)")
        assert next(answers) == {"X": 1}
        assert gc.get_threshold() == HOST  # suspended at an answer
        answers.close()  # abandoned with answers left
        assert gc.get_threshold() == HOST
        with pytest.raises(PrologTypeError):
            kb.holds("X is a + 1")
        assert gc.get_threshold() == HOST
        assert kb.holds("findall(X, q(X), [1, 2, 3])")  # nested solves
    assert seen == [QUERY_GEN0_THRESHOLD] * 4
    assert gc.get_threshold() == HOST


def test_a_host_that_retunes_during_a_query_keeps_its_setting(host_thresholds: None) -> None:
    kb = KnowledgeBase()

    @kb.predicate("retune", 0)
    def retune() -> object:
        gc.set_threshold(50_000, 5, 5)
        yield None

    with fast_queries():
        assert kb.holds("retune")
    assert gc.get_threshold() == (50_000, 5, 5)


def test_a_host_with_collection_off_or_higher_is_not_touched() -> None:
    before = gc.get_threshold()
    seen: list[int] = []
    kb = _kb(seen)
    try:
        for host in ((0, 10, 10), (2_000_000, 10, 10)):
            gc.set_threshold(*host)
            with fast_queries():
                assert kb.holds("q(1)")
            assert gc.get_threshold() == host
        assert seen == [0, 2_000_000]
    finally:
        gc.set_threshold(*before)

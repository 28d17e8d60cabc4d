"""Queries collect young garbage less often while they run, and restore the collector after."""

from __future__ import annotations

import gc

import pytest

from robocram.logic import KnowledgeBase, PrologTypeError
from robocram.logic.gc_pacing import QUERY_GEN0_THRESHOLD


def test_threshold_raised_while_running_and_restored_at_answers_errors_and_close() -> None:
    before = gc.get_threshold()
    kb = KnowledgeBase()
    seen: list[int] = []

    @kb.predicate("gen0", 1)
    def gen0(x: object) -> object:
        seen.append(gc.get_threshold()[0])
        yield None

    kb.consult("p(1). p(2). p(3).\nq(X) :- p(X), gen0(_).")
    answers = kb.query("q(X)")
    assert next(answers) == {"X": 1}
    assert gc.get_threshold() == before  # suspended at an answer
    answers.close()  # abandoned with answers left
    assert gc.get_threshold() == before
    assert seen == [QUERY_GEN0_THRESHOLD]
    with pytest.raises(PrologTypeError):
        kb.holds("X is a + 1")
    assert gc.get_threshold() == before
    assert kb.holds("findall(X, q(X), [1, 2, 3])")  # nested solves
    assert gc.get_threshold() == before

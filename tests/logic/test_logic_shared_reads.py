"""Texts and queries read once per process in the standard syntax, never across syntaxes.

A knowledge base whose operators changed reads ``1 - 2 - 3`` as ``1 - (2 - 3)`` (= 2), one
with the standard ones as ``(1 - 2) - 3`` (= -4): each must get its own reading whichever
read the text first."""

from __future__ import annotations

from robocram.logic import KnowledgeBase

TEXT = "s(X) :- X = (1 - 2 - 3)."
QUERY = "X = (1 - 2 - 3), Y is X"


def _right_minus() -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult(":- op(500, xfy, -).")
    return kb


def _value(kb: KnowledgeBase) -> object:
    answer = kb.first("s(X), Y is X")
    assert answer is not None
    return answer["Y"]


def test_a_text_read_in_the_standard_syntax_is_not_used_in_another() -> None:
    standard, other = KnowledgeBase(), _right_minus()
    standard.consult(TEXT, group="g")
    other.consult(TEXT, group="g")
    assert _value(standard) == -4 and _value(other) == 2
    again = KnowledgeBase()  # a third, standard: takes the kept reading
    again.consult(TEXT, group="g")
    assert _value(again) == -4


def test_a_text_read_in_another_syntax_is_not_kept_for_the_standard_one() -> None:
    other, standard = _right_minus(), KnowledgeBase()
    other.consult("s2(X) :- X = (1 - 2 - 3).", group="g")
    standard.consult("s2(X) :- X = (1 - 2 - 3).", group="g")
    a, b = other.first("s2(X), Y is X"), standard.first("s2(X), Y is X")
    assert a is not None and b is not None and (a["Y"], b["Y"]) == (2, -4)


def test_kept_clauses_are_each_knowledge_bases_own() -> None:
    first, second = KnowledgeBase(), KnowledgeBase()
    text = "n(1). n(2). n(3). m(X) :- n(X), X > 1."
    first.consult(text, group="nums")
    second.consult(text, group="nums")
    for _ in range(3):  # called enough to generate the clauses' code in the first only
        assert [a["X"] for a in first.query("m(X)")] == [2, 3]
    mine, theirs = first._preds[("m", 1)].clauses, second._preds[("m", 1)].clauses
    assert mine[0] is not theirs[0] and mine[0].head is theirs[0].head  # templates shared
    assert mine[0].calls > 0 and theirs[0].calls == 0  # counts (and code) their own
    assert [a["X"] for a in second.query("m(X)")] == [2, 3]


def test_a_query_is_read_in_each_syntax() -> None:
    standard, other = KnowledgeBase(), _right_minus()
    for kb, expected in ((standard, -4), (other, 2), (KnowledgeBase(), -4)):
        answer = kb.first(QUERY)
        assert answer is not None and answer["Y"] == expected

"""Clauses with complementary arithmetic guards leave no choicepoint (tak's two clauses).

`call_with_inference_limit/3` reports `!` when a goal left no choicepoint and `true`
when it did, which makes the choicepoint visible without timing anything.
"""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase

PROGRAM = """
le(X, Y, R) :- X =< Y, R = le.
le(X, Y, R) :- X > Y, R = gt.
sw(X, Y, R) :- X < Y, R = lt.
sw(X, Y, R) :- Y =< X, R = ge.
zero(N, R) :- N =:= 0, R = zero.
zero(N, R) :- N =\\= 0, R = other.
open_(X, Y, R) :- X =< Y, R = le.
open_(X, Y, R) :- X >= Y, R = ge.
bind(X, 1, R) :- X =< 5, R = small.
bind(X, _, R) :- X > 5, R = big.
"""


@pytest.fixture(scope="module")
def kb() -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult(PROGRAM)
    kb.holds("forall(between(1, 5, _), (le(1, 2, _), sw(1, 2, _), zero(0, _), open_(1, 2, _)))")
    kb.holds("forall(between(1, 5, _), ignore(bind(1, 1, _)))")
    return kb


@pytest.mark.parametrize(
    ("goal", "answers", "det"),
    [
        ("le(1, 2, R)", ["le"], "!"),
        ("le(3, 2, R)", ["gt"], "!"),
        ("sw(1, 2, R)", ["lt"], "!"),
        ("zero(0, R)", ["zero"], "!"),
        ("zero(4, R)", ["other"], "!"),
        ("open_(2, 2, R)", ["le", "ge"], "true"),  # not complementary: both may hold
    ],
)
def test_complementary_guards_leave_no_choicepoint(
    kb: KnowledgeBase, goal: str, answers: list[str], det: str
) -> None:
    found = kb.first(f"findall(R, {goal}, L), call_with_inference_limit({goal}, 1000, D)")
    assert found is not None and found["L"] == answers and found["D"] == det


def test_a_head_that_binds_keeps_the_later_clause(kb: KnowledgeBase) -> None:
    # bind(A, A, R): the first head binds A = 1 and its guard holds; on backtracking the
    # second clause sees A unbound and its guard raises, as without the optimisation.
    assert kb.holds("catch(findall(R, bind(A, A, R), _), error(instantiation_error, _), true)")

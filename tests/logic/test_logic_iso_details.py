"""The ISO details of issue 24 where SWI-Prolog was right and robocram was not.

Each expected term was checked against `swipl` 9.0.4 on the same goal.
"""

from __future__ import annotations

import re

import pytest

from robocram.logic import KnowledgeBase

CATCH = "catch(({goal}, R = true ; R = false), error(E, _), R = E)"


def _outcome(kb: KnowledgeBase, goal: str) -> str:
    """The goal's result as SWI prints it: true, false, or the formal error term."""
    kb.consult(f"outcome(R) :- {CATCH.format(goal=goal)}.")
    answer = kb.first("outcome(R), format(atom(A), '~q', [R])")
    kb.holds("retractall(outcome(_))")
    assert answer is not None
    return str(answer["A"])


@pytest.mark.parametrize(
    ("goal", "expected"),
    [
        ("abolish(foo/a)", "type_error(integer,a)"),
        ("abolish(1/2)", "type_error(atom,1)"),
        ("abolish(foo)", "type_error(predicate_indicator,foo)"),
        ("abolish(foo/(-1))", "domain_error(not_less_than_zero,-1)"),
        ("abolish(foo/_)", "instantiation_error"),
        ("abolish(foo/1.0)", "type_error(integer,1.0)"),
    ],
)
def test_abolish_names_the_bad_part_of_the_indicator(goal: str, expected: str) -> None:
    assert _outcome(KnowledgeBase(), goal) == expected


@pytest.mark.parametrize(
    ("goal", "expected"),
    [
        ("current_predicate(0/dog)", "type_error(predicate_indicator,0/dog)"),
        ("current_predicate(foo/a)", "type_error(predicate_indicator,foo/a)"),
        ("current_predicate(_/(-1))", "domain_error(not_less_than_zero,-1)"),
        ("current_predicate(_:nope/0)", "false"),
    ],
)
def test_current_predicate_checks_its_pattern(goal: str, expected: str) -> None:
    assert _outcome(KnowledgeBase(), goal) == expected


def test_asserted_variable_goals_are_stored_as_call() -> None:
    kb = KnowledgeBase()
    kb.holds("asserta((bar(X) :- X)), assertz((baz(Y) :- (Y -> true ; \\+ Y)))")
    assert kb.holds("clause(bar(A), B), B == call(A)")
    assert kb.holds("clause(baz(A), (G -> true ; \\+ H)), G == call(A), H == call(A)")


def test_a_clause_body_that_is_not_callable_is_the_culprit_whole() -> None:
    assert _outcome(KnowledgeBase(), "assertz((foo :- true, 4))") == "type_error(callable,(true,4))"


def test_char_code_checks_the_code_even_when_the_char_is_given() -> None:
    assert _outcome(KnowledgeBase(), "char_code(a, x)") == "type_error(integer,x)"


def test_the_debug_flag_takes_on_and_off_as_booleans() -> None:
    kb = KnowledgeBase()
    assert kb.first("set_prolog_flag(debug, on), current_prolog_flag(debug, F)") == {"F": "true"}
    assert kb.first("set_prolog_flag(debug, off), current_prolog_flag(debug, F)") == {"F": "false"}
    assert _outcome(kb, "set_prolog_flag(debug, xx)") == "type_error(bool,xx)"


@pytest.mark.parametrize(
    "goal", ["retract((atom(_) :- true))", "retract(atom(_))", "retractall(atom(_))"]
)
def test_retracting_a_built_in_is_modifying_a_static_procedure(goal: str) -> None:
    assert _outcome(KnowledgeBase(), goal) == "permission_error(modify,static_procedure,atom/1)"


def test_clause_of_a_built_in_is_still_a_private_procedure() -> None:
    assert _outcome(KnowledgeBase(), "clause(atom(_), _)") == (
        "permission_error(access,private_procedure,atom/1)"
    )


def test_setof_and_bagof_order_witness_groups_by_variable_age() -> None:
    kb = KnowledgeBase()
    for builtin in ("setof", "bagof"):
        for _ in range(20):  # ordering by address would pass only some of the time
            answer = kb.first(
                f"findall(L, {builtin}(X, member(X-_, [1-B, 2-_, 3-B, 4-C, 5-C]), L), R)"
            )
            assert answer is not None
            assert answer["R"] == [[1, 3], [2], [4, 5]]


def test_setof_sorts_fresh_variables_by_age() -> None:
    kb = KnowledgeBase()
    answer = kb.first("setof(X, member(X, [f(_), g, _, _]), L), L = [A, B | _], A \\== B")
    assert answer is not None


@pytest.mark.parametrize(
    ("goal", "expected"),
    [
        ("setof(X, X^(true ; 4), _)", "type_error(callable,(true;4))"),
        ("bagof(X, foo^(X = 1 ; 4), _)", "type_error(callable,(_=1;4))"),
        ("findall(X, (true ; 4), _)", "type_error(callable,(true;4))"),
    ],
)
def test_all_solutions_report_the_whole_goal_as_culprit(goal: str, expected: str) -> None:
    got = _outcome(KnowledgeBase(), goal)
    assert re.sub(r"_G?[0-9]*", "_", got) == expected

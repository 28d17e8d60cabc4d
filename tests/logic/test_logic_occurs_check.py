"""The `occurs_check` flag: false (cyclic terms allowed), true (fail), error (raise)."""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase, PrologOccursCheckError, Term

PROGRAM = "same(X, X).\npair(X, f(X)).\nwrap(X, Y) :- Y = g(X).\n"


def kb_with(flag: str) -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult(f":- set_prolog_flag(occurs_check, {flag}).\n{PROGRAM}")
    return kb


@pytest.mark.parametrize(
    "goal",
    ["X = f(X)", "same(X, f(X))", "pair(X, X)", "wrap(X, X)", "f(X, Y) = f(Y, g(X))"],
)
def test_occurs_check_true_fails_and_error_raises(goal: str) -> None:
    kb = kb_with("true")
    for _ in range(4):  # also once the clauses would run compiled
        assert not kb.holds(goal)
    kb = kb_with("error")
    for _ in range(2):
        with pytest.raises(PrologOccursCheckError) as info:
            kb.holds(goal)
        assert info.value.term[1][0][0] == "occurs_check"


def test_occurs_check_error_is_catchable_and_names_the_terms() -> None:
    kb = kb_with("error")
    goal = "catch(X = f(X), error(occurs_check(V, T), _), true), var(V), T = f(W), W == V"
    assert kb.first(goal) is not None


def test_occurs_check_flag_keeps_ordinary_answers_and_false_allows_cycles() -> None:
    for flag in ("true", "error"):
        kb = kb_with(flag)
        assert kb.first("pair(a, Y)") == {"Y": Term("f", ("a",))}
        assert kb.first("same(f(Y), f(b))") == {"Y": "b"}
        assert kb.first("current_prolog_flag(occurs_check, F)") == {"F": flag}
    kb = kb_with("false")
    assert kb.holds("_X = f(_X), \\+ acyclic_term(_X)")
    assert kb.holds("set_prolog_flag(occurs_check, true), \\+ _X = f(_X)")

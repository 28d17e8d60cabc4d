"""call_with_time_limit/2 and call_with_inference_limit/3, with SWI-Prolog's semantics.

Expected answers were checked against `swipl` 9.0.4 on the same goals.
"""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase

PROGRAM = """
g(1). g(2). g(3).
loop :- loop.
cnt(0) :- !.
cnt(N) :- M is N - 1, cnt(M).
outcome(G, R) :- catch((G -> R = true ; R = false), E, R = caught(E)).
"""


@pytest.fixture(scope="module")
def kb() -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult(PROGRAM)
    return kb


def _outcome(kb: KnowledgeBase, goal: str) -> object:
    answer = kb.first(f"outcome(({goal}), R), format(atom(T), '~w', [R])", max_inferences=10**7)
    assert answer is not None
    return answer["T"]


@pytest.mark.parametrize(
    ("goal", "expected"),
    [
        ("call_with_time_limit(0.05, loop)", "caught(time_limit_exceeded)"),
        ("call_with_time_limit(0, true)", "caught(time_limit_exceeded)"),
        ("call_with_time_limit(-1, true)", "caught(time_limit_exceeded)"),
        (
            "call_with_time_limit(5, call_with_time_limit(0.05, loop))",
            "caught(time_limit_exceeded)",
        ),
        (
            "call_with_time_limit(0.05, call_with_time_limit(5, loop))",
            "caught(time_limit_exceeded)",
        ),
        ("call_with_time_limit(5, fail)", "false"),
        ("call_with_time_limit(5, throw(foo))", "caught(foo)"),
    ],
)
def test_call_with_time_limit(kb: KnowledgeBase, goal: str, expected: str) -> None:
    assert _outcome(kb, goal) == expected


def test_call_with_time_limit_is_once_and_keeps_bindings(kb: KnowledgeBase) -> None:
    answer = kb.first("findall(X, call_with_time_limit(5, member(X, [1, 2])), L)")
    assert answer is not None and answer["L"] == [1]
    assert kb.first("call_with_time_limit(5, X = 3)") == {"X": 3}


def test_call_with_time_limit_checks_its_time(kb: KnowledgeBase) -> None:
    assert kb.holds(
        "catch(call_with_time_limit(a, true), error(type_error(evaluable, a/0), _), true)"
    )
    assert kb.holds("catch(call_with_time_limit(_, true), error(instantiation_error, _), true)")


@pytest.mark.parametrize(
    ("goal", "expected"),
    [
        ("findall(R-X, call_with_inference_limit(g(X), 100, R), L)", "[true-1,true-2,!-3]"),
        ("call_with_inference_limit(loop, 1000, L)", "inference_limit_exceeded"),
        ("call_with_inference_limit(cnt(100), 1000, L)", "!"),
        ("call_with_inference_limit(cnt(5000), 1000, L)", "inference_limit_exceeded"),
        ("call_with_inference_limit(true, 0, L)", "inference_limit_exceeded"),
        (
            "call_with_inference_limit(call_with_inference_limit(loop, 100000, A), 1000, B),"
            " L = A-B",
            "inference_limit_exceeded-!",
        ),
        (
            "call_with_inference_limit(call_with_inference_limit(loop, 1000, A), 100000, B),"
            " L = A-B",
            "inference_limit_exceeded-!",
        ),
        (
            "call_with_inference_limit(catch(loop, E, true), 1000, R), L = E-R",
            "inference_limit_exceeded-!",
        ),
    ],
)
def test_call_with_inference_limit(kb: KnowledgeBase, goal: str, expected: str) -> None:
    answer = kb.first(f"{goal}, format(atom(T), '~w', [L])", max_inferences=10**7)
    assert answer is not None and answer["T"] == expected


@pytest.mark.parametrize(
    ("goal", "error"),
    [
        ("call_with_inference_limit(true, a, _)", "type_error(integer, a)"),
        ("call_with_inference_limit(true, -1, _)", "domain_error(not_less_than_zero, -1)"),
        ("call_with_inference_limit(true, _, _)", "instantiation_error"),
    ],
)
def test_call_with_inference_limit_checks_its_limit(
    kb: KnowledgeBase, goal: str, error: str
) -> None:
    assert kb.holds(f"catch({goal}, error({error}, _), true)")


def test_inference_limit_failure_and_errors_pass_through(kb: KnowledgeBase) -> None:
    assert not kb.holds("call_with_inference_limit(fail, 10, _)")
    assert kb.holds("catch(call_with_inference_limit(throw(x), 10, _), x, true)")

"""assert/retract: the logical update view, and retract without copying the clause list."""

from __future__ import annotations

import itertools

from robocram.logic import KnowledgeBase


def test_running_call_keeps_its_clauses_while_others_are_retracted() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic q/1.\nq(1). q(2). q(3).")
    # Each answer of q(X) retracts every q/1 clause; the running call still sees all three.
    answer = kb.first("findall(_X, (q(_X), retractall(q(_))), L)")
    assert answer == {"L": [1, 2, 3]}
    assert kb.first("q(X)") is None


def test_running_call_does_not_see_clauses_asserted_after_it_started() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic r/1.\nr(1).")
    assert kb.first("findall(_X, (r(_X), _X < 5, _Y is _X + 1, assertz(r(_Y))), L)") == {"L": [1]}
    assert [a["X"] for a in kb.query("r(X)")] == [1, 2]


def test_retract_in_a_loop_keeps_order_and_compacts() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic item/1.")
    n = 3000
    for i in range(n):
        kb.assertz(f"item({i})")
    # Retract every even item through a running iteration (the logical update view).
    assert kb.holds("forall((item(X), X mod 2 =:= 0), retract(item(X)))")
    remaining = [a["X"] for a in kb.query("item(X)")]
    assert remaining == list(range(1, n, 2))
    pred = kb._preds[("item", 1)]
    assert len(pred.clauses) - pred.erased == n // 2
    assert pred.erased <= len(pred.clauses) // 2  # retracted ones are dropped in batches
    assert kb.holds("retract(item(1)), \\+ item(1), item(3)")


def test_retract_uses_first_argument_index() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic kv/2.")
    for i in range(500):
        kb.assertz(f"kv({i}, v{i})")
    assert kb.first("retract(kv(250, V))") == {"V": "v250"}
    assert kb.first("kv(250, V)") is None
    assert kb.first("kv(251, V)") == {"V": "v251"}
    assert kb.first("clause(kv(10, V), true)") == {"V": "v10"}


def test_asserta_100k_in_a_loop_keeps_order_and_count() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic(front/1).")
    n = 100_000
    assert kb.holds("between(1, N, I), asserta(front(I)), fail ; true", N=n)
    assert kb.first("aggregate_all(count, front(_), C)") == {"C": n}
    first = [a["X"] for a in itertools.islice(kb.query("front(X)"), 3)]
    assert first == [n, n - 1, n - 2]
    assert kb.first("findall(X, front(X), L), last(L, Last)")["Last"] == 1  # type: ignore[index]
    pred = kb._preds[("front", 1)]
    assert pred.head < n  # the room at the front is reused, not reallocated per clause


def test_asserta_during_a_running_call_is_not_seen_by_it() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic(s/1).\ns(1). s(2).")
    goal = "findall(X, (s(X), Y is X + 10, asserta(s(Y))), L)"
    goal = goal.replace("X", "_X").replace("Y", "_Y")
    assert kb.first(goal) == {"L": [1, 2]}
    assert [a["X"] for a in kb.query("s(X)")] == [12, 11, 1, 2]
    # the index keeps the new clauses in front: keyed and variable first arguments
    assert kb.first("s(11)") == {}
    kb.asserta("s(_)")
    assert len(list(kb.query("s(1)"))) == 2  # s(_) first, then s(1)
    assert len([a for a in kb.query("s(X)")]) == 5

"""retract/1 sees the clauses as they were at the call, without copying them (sieve).

The expected lists were checked against `swipl` 9.0.4.
"""

from __future__ import annotations

from robocram.logic import KnowledgeBase


def test_retract_ignores_clauses_added_while_it_runs() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic c/1.\nc(1).\nc(2).")
    answer = kb.first(
        "findall(_X, (retract(c(_X)), assertz(c(9)), asserta(c(8))), L), findall(_Y, c(_Y), M)"
    )
    assert answer == {"L": [1, 2], "M": [8, 8, 9, 9]}


def test_retract_skips_clauses_retracted_while_it_runs() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic d/1.\nd(a).\nd(b).\nd(c).")
    assert kb.first("findall(_Z, (retract(d(_Z)), retract(d(c))), L)") == {"L": ["a"]}


def test_retract_of_many_ground_facts_by_an_unbound_argument() -> None:
    kb = KnowledgeBase()
    kb.holds("forall(between(1, 3000, I), assertz(e(I)))")
    answer = kb.first("findall(X, retract(e(X)), L), length(L, N), \\+ e(_)")
    assert answer is not None and answer["N"] == 3000


def test_retracting_the_first_clause_again_and_again_keeps_the_order() -> None:
    # A queue: each retract starts past the clauses retracted before it (the skipped run
    # is remembered), and a clause put in front by asserta/1 is still found first.
    kb = KnowledgeBase()
    kb.holds("forall(between(1, 40, I), assertz(q(I)))")
    answer = kb.first(
        "findall(_X, (between(1, 5, _), once(retract(q(_X)))), A), asserta(q(0)),"
        " once(retract(q(Y))), once(retract(q(Z))), findall(_W, q(_W), Rest), length(Rest, N)"
    )
    assert answer == {"A": [1, 2, 3, 4, 5], "Y": 0, "Z": 6, "Rest": list(range(7, 41)), "N": 34}


def test_a_query_suspended_at_a_retract_answer_holds_no_lock() -> None:
    # Another thread's assert must not wait for a query left at retract/1's answer.
    import threading

    kb = KnowledgeBase()
    kb.consult(":- dynamic f/1.\nf(1).\nf(2).")
    answers = kb.query("retract(f(X))")
    assert next(answers) == {"X": 1}  # suspended inside retract/1, a later clause open
    done = threading.Event()
    writer = threading.Thread(target=lambda: (kb.assertz("f(3)"), done.set()), daemon=True)
    writer.start()
    writer.join(timeout=10)
    assert done.is_set(), "assertz/1 in another thread waited for the suspended retract/1"
    assert next(answers) == {"X": 2}
    assert kb.first("findall(_Y, f(_Y), L)") == {"L": [3]}

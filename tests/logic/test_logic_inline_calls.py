"""Calls of small guard predicates compiled into their callers answer as the calls do.

Each program runs twice: as written, and with the guards declared dynamic (never
compiled in), which is the reference.
"""

from __future__ import annotations

from typing import Any

import pytest

from robocram.logic import KnowledgeBase, PrologInstantiationError

PROGRAM = r"""
split([], _, [], []).
split([X|L], X, L1, L2) :- !, split(L, X, L1, L2).
split([X|L], Y, [X|L1], L2) :- before(X, Y), !, split(L, Y, L1, L2).
split([X|L], Y, L1, [X|L2]) :- before(Y, X), !, split(L, Y, L1, L2).
before(pair(A, _), pair(B, _)) :- A < B.
wrap(X, W) :- box(X, W), W = box(_, _).
wrap(X, none(X)).
box(X, box(X, Y)) :- Y = X.
twice(X, Y) :- same(X, Y), X == Y.
twice(_, no).
same(Z, Z).
first(X, R) :- guard(X), R = yes.
first(_, no).
guard(X) :- X > 0, !.
nth(N, T, R) :- pick(N, T, R), R \== b.
pick(N, T, A) :- arg(N, T, A), !.
use_total(L, S) :- total(L, S0), S is S0 * 2.
total(L, S) :- sum_acc(L, 0, S).
sum_acc([], S, S).
sum_acc([X|Xs], A, S) :- B is A + X, sum_acc(Xs, B, S).
choose(X, R) :- once_p(X), R = one.
choose(_, two).
once_p(X) :- p(X), !.
p(1).
p(2).
either(X, R) :- maybe(X), R = yes.
either(_, no).
maybe(X) :- ( X > 0, ! ; X < -5 ).
"""
GUARDS = "".join(
    f":- dynamic({p}).\n"
    for p in ["before/2", "box/2", "same/2", "guard/1", "pick/3", "total/2", "once_p/1", "maybe/1"]
)
QUERIES = [
    ("split([pair(1,b),pair(5,c),pair(3,x)], pair(3,x), A, B)", "A"),
    ("split([pair(3,a),pair(1,b),pair(5,c)], pair(3,x), A, B)", "B"),
    ("split([P, pair(1,b)], pair(3,x), A, B)", "A"),
    ("wrap(1, W)", "W"),
    ("wrap(W0, W), W0 = 2", "W"),
    ("twice(a, Y)", "Y"),
    ("twice(f(X), f(1))", "X"),
    ("first(1, R)", "R"),
    ("first(-1, R)", "R"),
    ("nth(2, f(a, b, c), R)", "R"),
    ("use_total([1, 2, 3], S)", "S"),
    ("choose(X, R)", "R"),
    ("either(3, R)", "R"),
    ("either(-9, R)", "R"),
    ("either(-1, R)", "R"),
]


def answers(kb: KnowledgeBase, text: str, key: str) -> list[str]:
    """The answers for `key`, asked often enough for the procedures to be compiled."""
    runs = [[repr(a[key]) for a in kb.query(text)] for _ in range(5)]
    assert all(r == runs[0] for r in runs)
    return runs[0]


def pair() -> tuple[KnowledgeBase, KnowledgeBase]:
    inlined, reference = KnowledgeBase(), KnowledgeBase()
    inlined.consult(PROGRAM, group="p")
    reference.consult(GUARDS + PROGRAM, group="p")
    return inlined, reference


def test_inlined_guards_answer_as_the_calls() -> None:
    inlined, reference = pair()
    for text, key in QUERIES:
        assert answers(inlined, text, key) == answers(reference, text, key), text
    assert answers(inlined, QUERIES[0][0], "A") == ["[pair(1,b)]"]
    assert answers(inlined, "wrap(1, W)", "W") == ["box(1,1)", "none(1)"]
    assert answers(inlined, "first(1, R)", "R") == ["'yes'", "'no'"]  # the guard's cut is its own
    # The guards were compiled in: the callers' code reads the knowledge base's generation.
    assert answers(inlined, "use_total([1, 2, 3], S)", "S") == ["12"]
    assert answers(inlined, "choose(X, R)", "R") == ["'one'", "'two'"]  # once_p's cut is its own
    assert answers(inlined, "either(3, R)", "R") == ["'yes'", "'no'"]
    for name, arity in [("split", 4), ("wrap", 2), ("twice", 2), ("first", 2), ("use_total", 2)]:
        proc: Any = inlined._preds[name, arity].proc
        assert proc is not None and "_generation" in proc.__code__.co_names, name
    # arg/3 may enumerate, a cut after a call or in a control construct is not a no-op:
    # those stay calls (made directly when the callee is a leaf: see direct_calls.py).
    for name, arity in [("nth", 3), ("choose", 2), ("either", 2)]:
        proc = inlined._preds[name, arity].proc
        assert proc is not None, name
        code = proc.__code__
        assert "_generation" not in code.co_names or "dr" in code.co_varnames, name


def test_a_changed_guard_is_called_again() -> None:
    inlined = KnowledgeBase()
    inlined.consult(PROGRAM, group="p", extendable=["before/2"])
    assert answers(inlined, QUERIES[0][0], "A") == ["[pair(1,b)]"]
    proc = inlined._preds[("split", 4)].proc
    inlined.consult("before(pair(A, _), pair(B, _)) :- A > B.", group="q")
    assert inlined._preds[("split", 4)].proc is proc  # the caller's code is kept
    assert answers(inlined, QUERIES[0][0], "A") == ["[pair(1,b), pair(5,c)]"]


def test_an_error_in_an_inlined_guard_is_raised() -> None:
    for kb in pair():
        answers(kb, QUERIES[0][0], "A")
        with pytest.raises(PrologInstantiationError):
            list(kb.query("split([pair(_,a)], pair(3,x), A, B)"))

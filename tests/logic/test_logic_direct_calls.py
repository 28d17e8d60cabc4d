"""A leading call of a compiled procedure, made from the caller's code, answers as the call.

Each program runs twice: as written, and with the callees declared dynamic (never
compiled, so never called directly), which is the reference.
"""

from __future__ import annotations

from typing import Any

from robocram.logic import KnowledgeBase
from robocram.logic.direct_calls import LEVELS, MAX_LEVEL

PROGRAM = r"""
pairs(X, Y) :- digit(X), digit(Y), X < Y.
pairs(0, 0).
digit(1). digit(2). digit(3).
sum(L, S) :- add(L, 0, S), S > 0.
add([], S, S).
add([X|Xs], A, S) :- B is A + X, add(Xs, B, S).
color_of(C, K) :- shade(C, K), K \== grey.
shade(a, red). shade(b, grey). shade(c, blue). shade(d, red). shade(e, green).
shade(f, grey). shade(g, red). shade(h, blue). shade(i, green). shade(j, red).
either(N) :- pairs(N, _).
either(none).
deep(0) :- !.
deep(N) :- digit(_), !, M is N - 1, deep(M).
"""
DYNAMIC = ":- dynamic digit/1.\n:- dynamic add/3.\n:- dynamic shade/2.\n"
QUERIES = [
    ("pairs(X, Y)", "Y"),
    ("findall(S, sum([1, 2, 3], S), L)", "L"),
    ("numlist(1, 2000, L), sum(L, S)", "S"),  # the callee hands its loop back
    ("color_of(C, K)", "C"),  # more clauses than a procedure scans: handed back
    ("color_of(d, K)", "K"),
    ("either(N)", "N"),
    ("deep(30000)", "_"),  # no Python recursion, however deep the Prolog one
]


def answers(kb: KnowledgeBase, text: str, key: str) -> list[str]:
    """The answers for `key`, asked often enough for the procedures to be compiled."""
    runs = [[repr(a.get(key)) for a in kb.query(text)] for _ in range(5)]
    assert all(r == runs[0] for r in runs)
    return runs[0]


def direct(kb: KnowledgeBase, name: str, arity: int) -> bool:
    """True when the predicate's procedure calls a leaf procedure directly."""
    proc: Any = kb._preds[name, arity].proc
    return proc is not None and "dr" in proc.__code__.co_varnames


def test_direct_calls_answer_as_the_calls() -> None:
    made, reference = KnowledgeBase(), KnowledgeBase()
    made.consult(PROGRAM, group="p")
    reference.consult(DYNAMIC + PROGRAM, group="p")
    for text, key in QUERIES:
        assert answers(made, text, key) == answers(reference, text, key), text
    assert answers(made, "pairs(X, Y)", "X") == ["1", "1", "2", "0"]
    assert answers(made, "numlist(1, 2000, L), sum(L, S)", "S") == ["2001000"]
    for name, arity in [("pairs", 2), ("sum", 2), ("color_of", 2), ("deep", 1)]:
        assert direct(made, name, arity), name
        assert not direct(reference, name, arity), name
    assert direct(made, "either", 1)  # pairs/2, itself making one, is low enough


def test_direct_calls_nest_no_deeper_than_max_level() -> None:
    """A chain of callers compiled callee first: the Python stack stays shallow."""
    chain = "".join(f"c{i}(X) :- c{i - 1}(X), X > 0.\nc{i}(0).\n" for i in range(1, 9))
    kb = KnowledgeBase()
    kb.consult(chain + "c0(1).\nc0(2).\n", group="p")
    for i in range(9):
        assert answers(kb, f"c{i}(X)", "X") == ["1", "2"] + ["0"] * (i > 0)
    # c5 would be at MAX_LEVEL + 1: it makes the call through the machine, and is at 0
    made = [i for i in range(1, 9) if direct(kb, f"c{i}", 1)]
    assert made == [i for i in range(1, 9) if i != MAX_LEVEL + 1]
    levels = [LEVELS[kb._preds[f"c{i}", 1].proc] for i in range(9)]  # type: ignore[index]
    assert levels == [0, 1, 2, 3, 4, 0, 1, 2, 3]


def test_a_changed_callee_is_called_again() -> None:
    kb = KnowledgeBase()
    kb.consult(PROGRAM, group="p", extendable=["digit/1"])
    assert answers(kb, "pairs(X, 3)", "X") == ["1", "2"]
    proc = kb._preds[("pairs", 2)].proc
    kb.consult("digit(0).", group="q")
    assert kb._preds[("pairs", 2)].proc is proc  # the caller's code is kept
    assert answers(kb, "pairs(X, 3)", "X") == ["1", "2", "0"]

"""Switching procedures (compiled after a few calls) answer like the clauses run in order."""

from __future__ import annotations

from typing import Any

import pytest

from robocram.logic import KnowledgeBase, PrologInstantiationError, PrologTypeError, Term
from robocram.logic.procedure import MAX_CLAUSES, SCAN_AFTER, compile_procedure

PROGRAM = """
len([], 0).
len([_|T], N) :- len(T, M), N is M + 1.
walk(_, [], done).
walk(K, [X|Xs], R) :- X > K, !, walk(K, Xs, R).
walk(_, [_|_], stopped).
shape(f(a), fa).
shape(g(X), X).
shape(h, atom_h).
shape(3, int3).
shape(3.0, float3).
ground_f(f(a), yes).
ground_f(g(b), no).
count(0) :- !.
count(N) :- N > 0, M is N - 1, count(M).
"""


def answers(kb: KnowledgeBase, text: str, key: str, times: int = 5) -> list[Any]:
    """Answers for `key`, asked enough times for the procedure to be compiled."""
    runs = [[a[key] for a in kb.query(text)] for _ in range(times)]
    assert all(r == runs[0] for r in runs)
    return runs[0]


@pytest.fixture()
def kb() -> KnowledgeBase:
    k = KnowledgeBase()
    k.consult(PROGRAM)
    return k


def test_procedure_compiled_for_every_small_static_predicate(kb: KnowledgeBase) -> None:
    for key in [("len", 2), ("count", 1), ("walk", 3), ("shape", 2)]:
        assert compile_procedure(kb._preds[key].clauses) is not None
    big = KnowledgeBase()
    big.consult(" ".join(f"f({i})." for i in range(MAX_CLAUSES + 1)))
    assert compile_procedure(big._preds[("f", 1)].clauses) is None  # indexed clause by clause


def test_procedure_keeps_clause_order_around_variable_heads() -> None:
    kb = KnowledgeBase()
    kb.consult("m(a, 1). m(X, 2) :- X \\== b. m(b, 3). m(f(_), 5). m(_, 4).")
    assert answers(kb, "m(a, R)", "R") == [1, 2, 4]
    assert answers(kb, "m(b, R)", "R") == [3, 4]
    assert answers(kb, "m(c, R)", "R") == [2, 4]
    assert answers(kb, "m(f(1), R)", "R") == [2, 5, 4]
    assert answers(kb, "m(1.0, R)", "R") == [2, 4]
    assert answers(kb, "m(X, R)", "R") == [1, 2, 3, 5, 4]


def test_procedure_cut_after_guard_commits() -> None:
    kb = KnowledgeBase()
    kb.consult("g(X, R) :- X > 0, !, X < 5, R = small. g(_, other).")
    assert answers(kb, "g(3, R)", "R") == ["small"]
    assert answers(kb, "g(10, R)", "R") == []  # committed by the cut, then X < 5 fails
    assert answers(kb, "g(-1, R)", "R") == ["other"]


def test_compiled_arithmetic_in_body_keeps_iso_errors() -> None:
    kb = KnowledgeBase()
    kb.consult("h(X, Y, Z) :- atom(a), Z is X * Y + 1, Z > X - 1.5.")
    assert answers(kb, "h(2, 3, Z)", "Z") == [7]
    assert answers(kb, "h(2.5, 2, Z)", "Z") == [6.0]
    assert answers(kb, "h(-1, 3, Z)", "Z") == [-2]
    assert answers(kb, "h(-2, 3, Z)", "Z") == []  # -5 > -3.5 fails
    for _ in range(3):
        with pytest.raises(PrologInstantiationError):
            kb.holds("h(2, _, _)")
        with pytest.raises(PrologTypeError):
            kb.holds("h(2, foo, _)")


def test_procedure_recursion_and_unbound_switch(kb: KnowledgeBase) -> None:
    assert answers(kb, "len([a, b, c], N)", "N") == [3]
    for _ in range(5):
        first = kb.first("len(L, 2)")
        assert first is not None and len(first["L"]) == 2
    assert answers(kb, "len(foo, N)", "N") == []


def test_procedure_switch_on_later_argument() -> None:
    kb = KnowledgeBase()
    kb.consult("na(_, [], _). na(Q, [Q1|Qs], D) :- Q =\\= Q1 + D, D1 is D + 1, na(Q, Qs, D1).")
    assert compile_procedure(kb._preds[("na", 3)].clauses) is not None
    for _ in range(5):
        assert kb.holds("na(1, [3, 5, 7], 1)")
        assert not kb.holds("na(5, [1, 3], 1)")
        assert kb.holds("na(1, [], 1)")
        with pytest.raises(PrologInstantiationError):
            kb.holds("na(1, [2], _)")


def test_procedure_ground_compound_key_checks_arguments(kb: KnowledgeBase) -> None:
    assert compile_procedure(kb._preds[("ground_f", 2)].clauses) is not None
    assert answers(kb, "ground_f(f(a), R)", "R") == ["yes"]
    assert answers(kb, "ground_f(f(b), R)", "R") == []
    assert answers(kb, "ground_f(g(b), R)", "R") == ["no"]
    assert answers(kb, "ground_f(X, R)", "R") == ["yes", "no"]


def test_procedure_deep_count_and_bad_input(kb: KnowledgeBase) -> None:
    for _ in range(4):
        assert kb.holds("count(100000)")
        assert not kb.holds("count(-1)")
    for _ in range(3):
        with pytest.raises(PrologTypeError, match="foo/0"):
            kb.holds("count(foo)")


def test_procedure_recompiled_when_group_reloads() -> None:
    kb = KnowledgeBase()
    kb.consult("color(red, warm). color(blue, cold).", group="colors")
    assert [kb.first("color(red, T)") for _ in range(5)][-1] == {"T": "warm"}
    assert kb._preds[("color", 2)].proc is not None
    kb.consult("color(red, hot). color(green, fresh).", group="colors")
    assert kb._preds[("color", 2)].proc is None
    for _ in range(5):
        assert kb.first("color(red, T)") == {"T": "hot"}
        assert kb.first("color(blue, T)") is None
        assert kb.first("color(green, T)") == {"T": "fresh"}


def test_procedure_skipped_for_dynamic_and_python(kb: KnowledgeBase) -> None:
    kb.consult(":- dynamic(seen/1).\nseen(a). seen(b).", group="d")
    for _ in range(4):
        assert kb.holds("seen(b)")
    assert kb._preds[("seen", 1)].proc is None  # dynamic: never switched
    kb.assertz("seen(c)")
    assert kb.holds("seen(c)")
    assert [a["X"] for a in kb.query("seen(X)")] == ["a", "b", "c"]


def test_procedure_and_clause_too_deep_to_compile_still_answer() -> None:
    kb = KnowledgeBase()
    n = 150
    names = ", ".join(f"X{i}" for i in range(n))
    kb.consult(f"p([{names}], X{n - 1}). p(foo, bar).")
    assert compile_procedure(kb._preds[("p", 2)].clauses) is None
    for _ in range(4):
        assert kb.first("p(L, Y)", L=list(range(n))) == {"Y": n - 1}
        assert kb.first("p(foo, Y)") == {"Y": "bar"}


def test_leading_if_then_else_on_tests_runs_inline() -> None:
    kb = KnowledgeBase()
    kb.consult(
        """
        kind(X, K) :- ( var(X) -> K = var ; integer(X), X > 10 -> K = big ; atom(X) -> K = atom
                      ; K = other ).
        pick(X, R) :- ( X > 0 -> !, R = pos ; R = nonpos ).
        pick(_, late).
        only(X, R) :- ( atom(X) -> R = yes ), true.
        only(_, second).
        """
    )
    assert answers(kb, "kind(_, K)", "K") == ["var"]
    assert answers(kb, "kind(42, K)", "K") == ["big"]
    assert answers(kb, "kind(7, K)", "K") == ["other"]
    assert answers(kb, "kind(a, K)", "K") == ["atom"]
    assert answers(kb, "kind(f(x), K)", "K") == ["other"]
    assert answers(kb, "pick(3, R)", "R") == ["pos"]  # the cut in Then cuts pick/2
    assert answers(kb, "pick(-3, R)", "R") == ["nonpos", "late"]
    assert answers(kb, "only(a, R)", "R") == ["yes", "second"]
    assert answers(kb, "only(1, R)", "R") == ["second"]  # no else: the first clause fails
    for _ in range(3):
        with pytest.raises(PrologTypeError):
            kb.holds("pick(foo, _)")


def test_long_self_recursion_that_fails_backtracks_into_alternatives() -> None:
    kb = KnowledgeBase()
    kb.consult("down(N) :- N > 0, M is N - 1, down(M).\ntry(X) :- ( down(5000) ; X = alt ).")
    for _ in range(4):  # loops past CHECK_EVERY in the procedure, then fails at 0
        assert kb.first("try(X)") == {"X": "alt"}


def test_unbound_first_argument_of_a_long_predicate_runs_clause_by_clause() -> None:
    kb = KnowledgeBase()
    n = SCAN_AFTER + 5
    kb.consult(" ".join(f"pop(c{i}, {i})." for i in range(n)) + " pop(X, -1) :- atom(X).")
    for _ in range(4):
        assert [a["P"] for a in kb.query("pop(C, P)")] == list(range(n))
        assert [a["P"] for a in kb.query("pop(c3, P)")] == [3, -1]
        assert [a["C"] for a in kb.query("pop(C, 4)")] == ["c4"]


def test_identity_tests_inline_and_as_builtins_agree() -> None:
    kb = KnowledgeBase()
    kb.consult("in(X, [Y|Ys]) :- ( X == Y -> true ; in(X, Ys) ).\nother(X, Y) :- X \\== Y.\n")
    for _ in range(4):
        assert kb.holds("in(f(A, 1), [g, f(B, 1), f(A, 1)])")
        assert not kb.holds("in(f(_, 1), [f(_, 1)])")  # different variables
        assert not kb.holds("in(1, [1.0])")
        assert kb.holds("other(1, 1.0), \\+ other(a, a), X = Y, \\+ other(X, Y)")
    assert kb.holds("_X = f(_X), _Y = f(_Y), _X == _Y")  # cyclic terms end


def test_later_clauses_see_arguments_as_called_after_a_shared_variable_was_bound() -> None:
    kb = KnowledgeBase()
    kb.consult("q([], []). q([a], [a]).\nr([], b). r([x], [x]).")
    # q(X, X): binding X for the first argument must not leak into the second argument
    # that the next clause (or the choicepoint) reads after the binding is undone.
    assert answers(kb, "q(X, X)", "X", times=6) == [[], ["a"]]
    assert answers(kb, "r(X, X)", "X", times=6) == [["x"]]


def test_clauses_whose_leading_type_test_refuses_the_switched_argument_are_skipped() -> None:
    kb = KnowledgeBase()
    kb.consult(
        """
        k(X, R) :- atomic(X), !, R = atomic.
        k(X, R) :- X \\== z, var(X), R = var.
        k(f(_), f).
        k(X, R) :- integer(X), R = int.
        k(_, other).
        c(X, R) :- !, atom(X), R = yes.
        c(_, no).
        """
    )
    assert answers(kb, "k(f(1), R)", "R") == ["f", "other"]
    assert answers(kb, "k(g, R)", "R") == ["atomic"]
    assert answers(kb, "k(7, R)", "R") == ["atomic"]
    assert answers(kb, "k(X, R)", "R") == ["var", "f", "other"]
    assert answers(kb, "k(2.5, R)", "R") == ["atomic"]
    assert answers(kb, "c(f(1), R)", "R") == []  # the cut commits before the test fails
    assert answers(kb, "c(a, R)", "R") == ["yes"]


def test_predicate_without_first_argument_keys_runs_every_clause_unswitched() -> None:
    # No head names its first argument: the procedure has no switch, and a compound,
    # an atom, a number or an unbound first argument all see every clause in order.
    kb = KnowledgeBase()
    kb.consult(
        "open(X, a) :- atom(X), !.\n"
        "open(X, b) :- compound(X).\n"
        "open(X, c) :- var(X), X = set.\n"
        "open(_, d).\n"
    )
    assert answers(kb, "open(f(1), R)", "R") == ["b", "d"]
    assert answers(kb, "open(x, R)", "R") == ["a"]
    assert answers(kb, "open(7, R)", "R") == ["d"]
    for _ in range(4):
        found = [(a["X"], a["R"]) for a in kb.query("open(X, R)")]
        assert [r for _, r in found] == ["c", "d"] and found[0][0] == "set"
    n = SCAN_AFTER + 3  # past SCAN_AFTER clauses the machine still runs them one by one
    kb.consult(" ".join(f"many(X, {i}) :- X = x{i}." for i in range(n)), group="many")
    assert answers(kb, "many(X, R)", "R") == list(range(n))
    assert answers(kb, "many(x3, R)", "R") == [3]


def test_procedures_of_one_shape_keep_their_own_constants_as_globals() -> None:
    # Same source text, different constants: one cached factory, two functions whose
    # constants are globals (no closure cell to copy into each call's frame).
    kb = KnowledgeBase()
    kb.consult("p(a, 1). p(b, 2). p(c, 3).\nq(x, 7). q(y, 8). q(z, 9).")
    assert answers(kb, "p(b, N)", "N") == [2]
    assert answers(kb, "q(z, N)", "N") == [9]
    assert answers(kb, "q(K, 7)", "K") == ["x"]
    p, q = kb._preds[("p", 2)].proc, kb._preds[("q", 2)].proc
    assert p is not None and q is not None
    assert p.__code__.co_freevars == () and p.__code__ is not q.__code__
    consts = [
        {v for k, v in f.__globals__.items() if k[0] == "k" and k[1:].isdigit()} for f in (p, q)
    ]
    assert {"a", "b", "c"} <= consts[0] and not {"x", "y", "z"} & consts[0]
    assert {"x", "y", "z"} <= consts[1]
    assert p.__globals__ is not q.__globals__
    assert p.__globals__["proc"] is p  # the name a choicepoint pushes


def test_a_procedures_locals_do_not_grow_with_its_clauses() -> None:
    # Each clause numbers its temporaries afresh: a call clears every local on return.
    def program(name: str, n: int) -> str:
        return " ".join(f"{name}(X, Y, c{i}) :- Y = g(X, h{i}), X > {i}." for i in range(n))

    kb = KnowledgeBase()
    kb.consult(program("small", 4) + "\n" + program("large", 40))
    assert answers(kb, "large(45, Y, c39)", "Y") == [Term("g", (45, "h39"))]
    assert answers(kb, "small(2, _, W)", "W") == ["c0", "c1"]
    small, large = kb._preds[("small", 3)].proc, kb._preds[("large", 3)].proc
    assert small is not None and large is not None
    assert large.__code__.co_nlocals <= small.__code__.co_nlocals + 2  # 40 clauses, not 4


@pytest.mark.parametrize("trail", [0, 400])
def test_a_failed_clause_unbinds_the_callers_variables_before_the_next(trail: int) -> None:
    # clause 1 binds X and Y (Y through a compound) and fails on its third argument; the
    # next clause must see both unbound, also with a long trail below (a choicepoint keeps
    # the trail of `length/2` and `maplist/2` alive); the dynamic twin runs no procedure
    text = "q(a, g(b), 1).\nq(X, Y, 2) :- var(X), var(Y), X = c, Y = d.\n"
    kb = KnowledgeBase()
    kb.consult(text + ":- dynamic(r/3).\n" + text.replace("q(", "r("))
    goal = f"between(1, 2, _), length(L, {trail}), maplist(=(z), L), P(X, Y, 2)"
    for _ in range(4):  # compiled after a few calls
        got = [(a["X"], a["Y"]) for a in kb.query(goal.replace("P(", "q("))]
        assert got == [(a["X"], a["Y"]) for a in kb.query(goal.replace("P(", "r("))]
        assert got == [("c", "d"), ("c", "d")]

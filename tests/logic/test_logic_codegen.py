"""Compiled clauses answer exactly like interpreted ones (clauses compile on their 2nd call)."""

from __future__ import annotations

from typing import Any

import pytest

from robocram.logic import (
    KnowledgeBase,
    PrologError,
    PrologInstantiationError,
    PrologTypeError,
    Term,
)
from robocram.logic.codegen import compile_clause_fn

PROGRAM = """
app([], L, L).
app([H|T], L, [H|R]) :- app(T, L, R).
deep(f(g(X, [a, Y|T]), X), Y, T).
kind(1, int). kind(1.0, float). kind(one, atom). kind("one", string). kind(f(_), compound).
pick(X, Y) :- X > 2, !, Y = big.
pick(_, small).
step(N, M) :- M is N * 2 + 1 - 3.
same(X, Y) :- X = Y.
selfref :- X = f(X), X = f(Y), Y = f(_).
cmp(A, B, lt) :- A < B.
cmp(A, B, ge) :- A >= B.
neg(X, Y) :- Y is -X.
fl(X, Y) :- Y is X / 2.
"""


def run_twice(kb: KnowledgeBase, text: str, **b: Any) -> list[dict[str, Any]]:
    """Run a query three times (interpreted, compiling, compiled); answers must agree."""
    answers = [list(kb.query(text, **b)) for _ in range(3)]
    assert answers[0] == answers[1] == answers[2]
    return answers[0]


@pytest.fixture()
def kb() -> KnowledgeBase:
    k = KnowledgeBase()
    k.consult(PROGRAM)
    return k


def test_codegen_append_modes(kb: KnowledgeBase) -> None:
    assert run_twice(kb, "app([1, 2], [3], L)") == [{"L": [1, 2, 3]}]
    splits = run_twice(kb, "app(X, Y, [1, 2])")
    assert splits == [
        {"X": [], "Y": [1, 2]},
        {"X": [1], "Y": [2]},
        {"X": [1, 2], "Y": []},
    ]
    assert run_twice(kb, "app([1|T], [9], [1, 2, 9])") == [{"T": [2]}]
    assert run_twice(kb, "app([1], [2], [1, 3])") == []


def test_codegen_nested_head_read_and_write(kb: KnowledgeBase) -> None:
    assert run_twice(kb, "deep(f(g(1, [a, b, c]), 1), Y, T)") == [{"Y": "b", "T": ["c"]}]
    assert run_twice(kb, "deep(f(g(1, [a, b]), 2), Y, T)") == []
    for _ in range(3):
        written = kb.first("deep(D, 7, [8]), D = f(g(X, L), Z), X == Z")
        assert written is not None
        assert written["L"] == ["a", 7, 8]
        assert written["D"] == Term("f", (Term("g", (written["X"], ["a", 7, 8])), written["X"]))


def test_codegen_constants_match_exact_types(kb: KnowledgeBase) -> None:
    assert run_twice(kb, "kind(1, K)") == [{"K": "int"}]
    assert run_twice(kb, "kind(1.0, K)") == [{"K": "float"}]
    assert run_twice(kb, "kind(one, K)") == [{"K": "atom"}]
    assert run_twice(kb, 'kind("one", K)') == [{"K": "string"}]
    assert run_twice(kb, "kind(f(2), K)") == [{"K": "compound"}]
    assert [a["K"] for a in run_twice(kb, "kind(_, K)")] == [
        "int",
        "float",
        "atom",
        "string",
        "compound",
    ]


def test_codegen_inline_cut_and_arithmetic(kb: KnowledgeBase) -> None:
    assert run_twice(kb, "pick(5, Y)") == [{"Y": "big"}]
    assert run_twice(kb, "pick(1, Y)") == [{"Y": "small"}]
    assert run_twice(kb, "step(4, M)") == [{"M": 6}]
    assert run_twice(kb, "step(2.5, M)") == [{"M": pytest.approx(3.0)}]
    assert run_twice(kb, "step(4, 6)") == [{}]
    assert run_twice(kb, "step(4, 7)") == []
    assert run_twice(kb, "neg(3, Y)") == [{"Y": -3}]
    assert run_twice(kb, "fl(3, Y)") == [{"Y": pytest.approx(1.5)}]
    assert [a["R"] for a in run_twice(kb, "cmp(1, 2.0, R)")] == ["lt"]
    assert [a["R"] for a in run_twice(kb, "cmp(2, 2, R)")] == ["ge"]


def test_codegen_inline_unify(kb: KnowledgeBase) -> None:
    assert run_twice(kb, "same(f(A), f(1))") == [{"A": 1}]
    for _ in range(3):
        assert kb.holds("same(X, Y), X == Y")
    assert run_twice(kb, "same(1, 2)") == []
    for _ in range(3):
        assert kb.holds("selfref")


@pytest.mark.parametrize("query", ["step(_, M)", "cmp(_, 1, R)"])
def test_codegen_inline_arith_unbound_raises(kb: KnowledgeBase, query: str) -> None:
    for _ in range(3):
        with pytest.raises(PrologInstantiationError):
            list(kb.query(query))


def test_codegen_inline_arith_type_error_names_culprit(kb: KnowledgeBase) -> None:
    for _ in range(3):
        with pytest.raises(PrologTypeError, match="foo/0"):
            list(kb.query("step(foo, M)"))
    for _ in range(3):
        answer = kb.first("catch(step(foo, _), error(type_error(T, C), _), true)")
        assert answer == {"T": "evaluable", "C": Term("/", ("foo", 0))}


def test_codegen_factories_shared_by_shape() -> None:
    kb = KnowledgeBase()
    kb.consult("\n".join(f"fact({i}, v{i})." for i in range(50)))
    clauses = kb._preds[("fact", 2)].clauses
    fns = [compile_clause_fn(c) for c in clauses[:3]]
    assert fns[0].__code__ is fns[1].__code__ is fns[2].__code__
    assert [a["V"] for a in kb.query("fact(7, V)")] == ["v7"]
    assert kb.first("fact(K, v42)") == {"K": 42}


def test_codegen_deep_recursion_bounded() -> None:
    kb = KnowledgeBase()
    kb.consult("count(0). count(N) :- N > 0, M is N - 1, count(M).")
    assert kb.holds("count(200000)")
    with pytest.raises(PrologError):
        kb.holds("count(foo)")


def test_codegen_self_tail_call_after_backtracking() -> None:
    kb = KnowledgeBase()
    kb.consult("cnt(N, N) :- N >= 3. cnt(N, M) :- N < 3, N1 is N + 1, cnt(N1, M).")
    for _ in range(3):
        assert [a["L"] for a in kb.query("findall(M, cnt(0, M), L)")] == [[3]]
        assert [a["L"] for a in kb.query("findall(M, cnt(5, M), L)")] == [[5]]


def test_codegen_self_tail_call_reaches_python_predicate() -> None:
    kb = KnowledgeBase()
    kb.consult("walk(N, R) :- N > 0, M is N - 1, walk(M, R).")

    @kb.predicate("walk", 2)
    def walk(n: Any, r: Any) -> Any:
        if n == 0:
            yield (0, "bottom")

    for _ in range(3):
        assert [a["R"] for a in kb.query("walk(4, R)")] == ["bottom"]


def test_codegen_arithmetic_on_variable_chains(kb: KnowledgeBase) -> None:
    for _ in range(3):
        assert kb.first(
            "X = Y, Y = Z, Z = 4, step(X, M)",
        ) == {
            "X": 4,
            "Y": 4,
            "Z": 4,
            "M": 6,
        }
        assert [a["R"] for a in kb.query("A = B, B = 1.5, cmp(A, 2, R)")] == ["lt"]


def test_codegen_compiled_binary_functions_keep_iso_errors() -> None:
    kb = KnowledgeBase()
    kb.consult("f(A, B, R) :- R is (A * 3) mod B + max(A, B) // 2 + 2 ** B.")
    for _ in range(3):
        assert kb.first("f(7, 4, R)") == {"R": 1 + 3 + 16}
        assert kb.first("f(-7, 4, R)") == {"R": 3 + 2 + 16}
        caught = kb.first("catch(f(7, 0, _), error(E, _), true)")
        assert caught == {"E": Term("evaluation_error", ("zero_divisor",))}
        caught = kb.first("catch(f(7, 2.0, _), error(E, _), true)")
        assert caught == {"E": Term("type_error", ("integer", 2.0))}
        with pytest.raises(PrologInstantiationError):
            kb.holds("f(7, _, _)")


def test_type_test_after_binding_a_tested_variable_sees_the_binding() -> None:
    kb = KnowledgeBase()
    kb.consult(
        """
        p(X) :- var(X), X = a, atom(X).
        q(X, Y) :- var(X), X = Y, integer(X).
        m(P, R) :- nonvar(P), P = star(S), !, R = S.
        m(P, P).
        """
    )
    assert run_twice(kb, "p(X)") == [{"X": "a"}]
    assert run_twice(kb, "q(X, 3)") == [{"X": 3}]
    assert run_twice(kb, "q(X, a)") == []
    assert run_twice(kb, "m(star(1), R)") == [{"R": 1}]
    assert run_twice(kb, "m(plain, R)") == [{"R": "plain"}]
    assert run_twice(kb, "m(star, R)") == [{"R": "star"}]


def test_inline_goals_after_a_call_run_as_one_step_with_iso_errors() -> None:
    kb = KnowledgeBase()
    kb.consult(
        """
        val(3). val(4). val(a).
        sq(X, Y) :- val(X), integer(X), Y is X * X, Y > 9, Z = X, Z == X.
        even(X) :- val(X), integer(X), 0 is X mod 2.
        half(X, H) :- val(X), H is X // 2.
        bad(Y) :- val(_), Y is foo + 1.
        unb(Y) :- val(_), Y > 1.
        """
    )
    assert run_twice(kb, "sq(X, Y)") == [{"X": 4, "Y": 16}]
    assert run_twice(kb, "even(X)") == [{"X": 4}]
    assert [a["H"] for a in run_twice(kb, "half(3, H)")] == [1]
    for _ in range(3):
        with pytest.raises(PrologTypeError):
            kb.holds("bad(_)")
        with pytest.raises(PrologInstantiationError):
            kb.holds("unb(_)")
        with pytest.raises(PrologTypeError):
            kb.holds("X = a, half(X, _)")


def test_univ_in_clause_code_both_ways_leading_and_after_a_call() -> None:
    kb = KnowledgeBase()
    kb.consult(
        """
        dec(T, F, As) :- T =.. [F|As].
        com(F, As, T) :- T =.. [F|As].
        later(T, F, As) :- atom_length(abc, _), T =.. [F|As], atom(F).
        whole(T, L) :- T =.. L.
        """
    )
    assert run_twice(kb, "dec(f(a, B), F, As), As == [a, B]", B=1) == [{"F": "f", "As": ["a", 1]}]
    assert run_twice(kb, "dec(f(a, b), F, As)") == [{"F": "f", "As": ["a", "b"]}]
    assert run_twice(kb, "dec(foo, F, As)") == [{"F": "foo", "As": []}]
    assert run_twice(kb, "dec(3, F, As)") == [{"F": 3, "As": []}]
    assert run_twice(kb, "dec(T, g, [1, 2])") == [{"T": Term("g", (1, 2))}]
    assert run_twice(kb, "com(g, [1, 2], T)") == [{"T": Term("g", (1, 2))}]
    assert run_twice(kb, "com(x, [], T)") == [{"T": "x"}]
    assert run_twice(kb, "later(T, h, [z])") == [{"T": Term("h", ("z",))}]
    assert run_twice(kb, "later(h(z), F, As)") == [{"F": "h", "As": ["z"]}]
    assert run_twice(kb, "later(7, F, As)") == []
    assert run_twice(kb, "whole(f(1), [f, 2])") == []
    for _ in range(3):
        with pytest.raises(PrologInstantiationError):
            kb.holds("com(_, _, _)")
        with pytest.raises(PrologTypeError):
            kb.holds("com(1, [a], _)")
        caught = kb.first("catch(whole(_, []), error(E, _), true)")
        assert caught is not None and caught["E"] == Term("domain_error", ("non_empty_list", []))


def test_guards_checked_early_keep_prolog_order_of_failure_and_errors() -> None:
    kb = KnowledgeBase()
    kb.consult(
        """
        p([X|_], Y, [X]) :- X < Y.
        r(X, Y, f(X)) :- X < Y + 0.
        c(X, [_]) :- !, X > 1.
        c(_, _).
        t(X, g(X)) :- atom(X).
        t(_, other).
        """
    )
    assert run_twice(kb, "p([1], 2, Z)") == [{"Z": [1]}]
    assert run_twice(kb, "p([3], 2, Z)") == []
    assert run_twice(kb, "p([a], 1, [b])") == []  # the head fails before the guard
    assert run_twice(kb, "r(A, 2, f(1))") == [{"A": 1}]  # bound by a later argument
    assert run_twice(kb, "c(0, [a])") == []  # the cut comes first
    assert run_twice(kb, "t(1, R)") == [{"R": "other"}]
    assert run_twice(kb, "t(a, R)") == [{"R": Term("g", ("a",))}, {"R": "other"}]
    for _ in range(3):
        with pytest.raises(PrologTypeError):
            kb.holds("p([a], 1, _)")
        with pytest.raises(PrologInstantiationError):
            kb.holds("r(_, 2, _)")


def test_python_tuples_called_as_goals_are_type_errors_never_calls() -> None:
    kb = KnowledgeBase()
    kb.consult("foo. call_it(G) :- true, G.\nboth(G) :- member(X, [G]), X, true.")
    for goal in [("foo", ()), ("foo", (), None), (1, 2), ()]:
        for query in ["call_it(G)", "both(G)", "G", "(true, G)"]:
            for _ in range(3):
                with pytest.raises(PrologTypeError, match="callable"):
                    kb.holds(query, G=goal)
    spelled = Term(",", ("true", ("foo", ())))
    for _ in range(3):
        with pytest.raises(PrologTypeError, match="callable"):
            kb.holds("call_it(G)", G=spelled)
    assert kb.holds("call_it(foo), both(foo)")


def test_calls_from_compiled_clauses_name_their_predicate_in_errors() -> None:
    kb = KnowledgeBase()
    kb.consult("go(X) :- atom(X), missing_pred(X, 1).\nboom(X) :- atom(X), py_fail(X).")

    @kb.predicate("py_fail", 1)
    def py_fail(x: object) -> Any:
        raise ValueError("no")
        yield None

    for _ in range(4):
        caught = kb.first("catch(go(a), error(E, _), true)")
        assert caught is not None
        assert caught["E"] == Term("existence_error", ("procedure", Term("/", ("missing_pred", 2))))
        with pytest.raises(ValueError, match="no"):
            kb.holds("boom(a)")


def test_control_constructs_in_clause_code_after_a_call() -> None:
    kb = KnowledgeBase()
    kb.consult(
        """
        v(1). v(2). v(3).
        ite(X, R) :- v(X), ( v(2), X > 1 -> R = big ; X =:= 1 -> R = one ; R = other ).
        soft(X, R) :- v(X), ( v(Y), Y > X *-> R = Y ; R = none ).
        neg(X) :- v(X), \\+ ( v(Y), Y > X ).
        pyt(T) :- v(_), ( T ; true ).
        """
    )
    assert run_twice(kb, "ite(X, R)") == [
        {"X": 1, "R": "one"},
        {"X": 2, "R": "big"},
        {"X": 3, "R": "big"},
    ]
    assert [(a["X"], a["R"]) for a in run_twice(kb, "soft(X, R)")] == [
        (1, 2),
        (1, 3),
        (2, 3),
        (3, "none"),
    ]
    assert run_twice(kb, "neg(X)") == [{"X": 3}]
    for _ in range(3):
        with pytest.raises(PrologTypeError, match="callable"):
            kb.holds("pyt(T)", T=("a", (), None))


def test_is_into_a_new_variable_after_a_call_binds_it_again_on_backtracking() -> None:
    # `Y is E` after a call binds the new Y directly; backtracking into the call undoes it.
    kb = KnowledgeBase()
    kb.consult(
        "v(1). v(2). v(3).\n"
        "tens(X, Y) :- v(X), Y is X * 10.\n"
        "alias(X, Y) :- v(X), Z = Y, Z is X + 1.\n"
        "twice(X, Y) :- v(X), Y is X + 1, Y is X + 1.\n"
        "undef(X) :- v(_), X is Y + 1, Y = 1.\n"
    )
    assert [(a["X"], a["Y"]) for a in run_twice(kb, "tens(X, Y)")] == [(1, 10), (2, 20), (3, 30)]
    assert [(a["X"], a["Y"]) for a in run_twice(kb, "alias(X, Y)")] == [(1, 2), (2, 3), (3, 4)]
    assert [a["Y"] for a in run_twice(kb, "twice(_, Y)")] == [2, 3, 4]
    assert run_twice(kb, "tens(2, 21)") == []
    for _ in range(3):
        with pytest.raises(PrologInstantiationError):
            kb.holds("undef(_)")


def test_small_ground_compounds_in_heads_read_and_bind_like_unify() -> None:
    kb = KnowledgeBase()
    kb.consult("g([a, b], f(1, x)).\ng([a], one).\ng(f(2.0), float).\n")
    assert [a["X"] for a in run_twice(kb, "g(X, _)")] == [["a", "b"], ["a"], Term("f", (2.0,))]
    assert [a["T"] for a in run_twice(kb, "g([a|T], _)")] == [["b"], []]
    assert run_twice(kb, "g([a, b], f(N, x))") == [{"N": 1}]
    assert run_twice(kb, "g([a, c], _)") == []
    assert run_twice(kb, "g(f(2), _)") == []
    assert run_twice(kb, "g([a, B|T], Y)") == [{"B": "b", "T": [], "Y": Term("f", (1, "x"))}]

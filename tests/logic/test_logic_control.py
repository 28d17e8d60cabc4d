"""Control constructs: cut in its classic places, if-then-else, soft-cut, negation, catch."""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase, PrologThrow, PrologTypeError


@pytest.fixture()
def kb() -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult(
        """
        p(1). p(2). p(3).
        first(X) :- p(X), !.
        body_cut(X, Y) :- p(X), !, p(Y).
        body_cut(9, 9).
        ite(X, R) :- ( X > 1 -> R = big ; R = small ).
        cut_in_then(X) :- ( true -> p(X), ! ; true ).
        cut_in_cond(X) :- ( p(X), ! -> true ; true ).
        cut_in_call(X) :- call((p(X), !)).
        cut_in_call_all(X) :- call((p(X), !)) ; X = 4.
        cut_in_naf(X) :- p(X), \\+ (p(Y), !, Y > 1).
        transparent(X) :- ( p(X), X > 1, ! ; X = 0 ).
        soft(X, Y) :- ( p(X) *-> Y = yes ; Y = no ).
        soft_none(Y) :- ( fail *-> Y = yes ; Y = no ).
        """
    )
    return kb


def values(kb: KnowledgeBase, query: str, var: str = "X") -> list[object]:
    return [a[var] for a in kb.query(query)]


def test_cut_in_body_commits_to_first_solution(kb: KnowledgeBase) -> None:
    assert values(kb, "first(X)") == [1]
    assert [(a["X"], a["Y"]) for a in kb.query("body_cut(X, Y)")] == [(1, 1), (1, 2), (1, 3)]


def test_if_then_else_and_cut_barriers(kb: KnowledgeBase) -> None:
    assert values(kb, "ite(3, R)", "R") == ["big"]
    assert values(kb, "ite(0, R)", "R") == ["small"]
    assert values(kb, "cut_in_then(X)") == [1]
    assert values(kb, "cut_in_cond(X)") == [1]
    assert values(kb, "(p(X) -> true ; true)") == [1]
    assert values(kb, "transparent(X)") == [2]


def test_cut_inside_call_is_local(kb: KnowledgeBase) -> None:
    assert values(kb, "cut_in_call(X)") == [1]
    assert values(kb, "cut_in_call_all(X)") == [1, 4]
    assert values(kb, "call((p(X), !)) ; X = 5") == [1, 5]


def test_cut_inside_negation_is_local(kb: KnowledgeBase) -> None:
    assert values(kb, "cut_in_naf(X)") == [1, 2, 3]
    assert values(kb, "p(X), \\+ X = 2") == [1, 3]
    assert kb.holds("\\+ fail") and not kb.holds("\\+ true")


def test_soft_cut_keeps_condition_choicepoints(kb: KnowledgeBase) -> None:
    assert [(a["X"], a["Y"]) for a in kb.query("soft(X, Y)")] == [
        (1, "yes"),
        (2, "yes"),
        (3, "yes"),
    ]
    assert values(kb, "soft_none(Y)", "Y") == ["no"]


def test_once_ignore_disjunction(kb: KnowledgeBase) -> None:
    assert values(kb, "once(p(X))") == [1]
    assert values(kb, "ignore(p(X))") == [1]
    assert kb.first("ignore(fail)") == {}
    assert values(kb, "(X = a ; X = b)") == ["a", "b"]
    assert kb.holds("not(fail)") and not kb.holds("false")


def test_call_n_adds_arguments(kb: KnowledgeBase) -> None:
    assert values(kb, "G = p, call(G, X)") == [1, 2, 3]
    assert kb.first("call(format(atom(A)), '~w-~w', [x, y])") == {"A": "x-y"}
    assert kb.first("call(plus(1), 2, Z)") == {"Z": 3}


def test_catch_and_throw(kb: KnowledgeBase) -> None:
    assert kb.first("catch(throw(oops), E, true)") == {"E": "oops"}
    answer = kb.first("catch(X is foo + 1, error(type_error(T, C), _), true)")
    assert answer is not None and answer["T"] == "evaluable"
    assert answer["C"].name == "/" and answer["C"].args == ("foo", 0)
    assert kb.first("catch(X is 1 / 0, error(evaluation_error(E), _), true)")["E"] == "zero_divisor"  # type: ignore[index]
    with pytest.raises(PrologThrow) as info:
        kb.holds("catch(throw(a), b, true)")
    assert info.value.term == "a"
    assert kb.first("catch(catch(throw(in), out, R = 1), in, R = 2)") == {"R": 2}


def test_catch_undoes_bindings_and_only_protects_its_goal(kb: KnowledgeBase) -> None:
    assert kb.first("catch((X = 1, throw(e)), e, true)") is not None
    answer = kb.first("catch((X = 1, throw(e)), e, Y = caught)")
    assert answer is not None and answer["Y"] == "caught" and not isinstance(answer["X"], int)
    with pytest.raises(PrologThrow):
        kb.holds("catch(p(X), _, true), X > 1, throw(late)")
    assert values(kb, "catch(p(X), _, true), X > 1") == [2, 3]


def test_uncaught_iso_error_surfaces_as_python_exception(kb: KnowledgeBase) -> None:
    with pytest.raises(PrologTypeError) as info:
        kb.holds("X is a + 1")
    assert info.value.term.args[0].name == "type_error"
    with pytest.raises(PrologTypeError):
        kb.holds("throw(error(type_error(integer, x), ctx))")


def test_compiled_control_constructs_in_clause_bodies() -> None:
    # Disjunctions, if-then(-else) and conjunctions inside a body run as marked goals;
    # cut stays transparent in a branch and local to a condition. Checked against swipl.
    kb = KnowledgeBase()
    kb.consult(
        "m(1). m(2). m(3).\n"
        "t1(X) :- m(X), (X > 1, ! ; fail).\n"
        "t2(X) :- m(Y), (Y >= 2 -> X = Y ; X = none).\n"
        "t3(X) :- m(X), (m(Z), Z > 1, !, Z == 2 -> true ; true).\n"
        "t4(X) :- m(Y), (Y > 5 -> X = Y).\n"
        "t4(late).\n"
        "t5(X) :- m(A), (A = 1, m(B) ; A = 2, B = x), X = A-B.\n"
        "t6(L) :- findall(X-Y, (m(X), (X = 1 -> Y = a ; X = 2 -> Y = b ; Y = c)), L).\n"
    )
    assert [a["X"] for a in kb.query("t1(X)")] == [2]
    assert [a["X"] for a in kb.query("t2(X)")] == ["none", 2, 3]
    assert [a["X"] for a in kb.query("t3(X)")] == [1, 2, 3]
    assert [a["X"] for a in kb.query("t4(X)")] == ["late"]
    assert [str(a["X"]) for a in kb.query("t5(X)")] == ["1-1", "1-2", "1-3", "2-x"]
    answer = kb.first("t6(L)")
    assert answer is not None and str(answer["L"]) == "[1-a, 2-b, 3-c]"


def test_then_branch_true_after_a_call() -> None:
    # `( C -> true ; E )` and `( C -> true )` after a call leave no goal for the then
    # branch: the condition's choicepoints still go, the else branch still runs.
    kb = KnowledgeBase()
    kb.consult(
        "m(1). m(2). m(3).\n"
        "u1(X) :- m(A), ( m(X), X > A -> true ; X = none ).\n"
        "u2(X) :- m(X), ( m(Y), Y > X -> true ).\n"
        "u3(X-Y) :- m(X), ( X > 1 -> true, true ; Y = small ).\n"
        "u4(R) :- m(_), ( fail -> true ; R = else ), !.\n"
    )
    for _ in range(4):  # the first calls run clause by clause, later ones a procedure
        assert [a["X"] for a in kb.query("u1(X)")] == [2, 3, "none"]
        assert [a["X"] for a in kb.query("u2(X)")] == [1, 2]
        answers = [str(a["P"]) for a in kb.query("u3(P)")]
        assert answers[0] == "1-small" and len(answers) == 3
        assert answers[1].startswith("2-_") and answers[2].startswith("3-_")
        assert [a["R"] for a in kb.query("u4(R)")] == ["else"]

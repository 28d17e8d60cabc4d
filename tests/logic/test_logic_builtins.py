"""Every built-in, checked by value."""

from __future__ import annotations

import pytest

from robocram.logic import (
    KnowledgeBase,
    PrologEvaluationError,
    PrologInstantiationError,
    PrologTypeError,
    Term,
)


@pytest.fixture(scope="module")
def kb() -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult("age(ann, 31). age(bob, 25). age(cid, 31). even(X) :- 0 is X mod 2.")
    return kb


def one(kb: KnowledgeBase, query: str, var: str = "X") -> object:
    answer = kb.first(query)
    assert answer is not None, query
    return answer[var]


@pytest.mark.parametrize(
    ("query", "expected"),
    [
        ("X is 7 + 3 * 2", 13),
        ("X is 7 / 2", 3.5),
        ("X is 8 / 2", 4),
        ("X is 7 // 2", 3),
        ("X is -7 // 2", -3),
        ("X is -7 mod 2", 1),
        ("X is -7 rem 2", -1),
        ("X is 2 ** 10", 1024),
        ("X is 2 ^ 3", 8),
        ("X is max(3, 4.5) - min(1, 2)", 3.5),
        ("X is abs(-3) + sign(-2)", 2),
        ("X is sqrt(16.0)", 4.0),
        ("X is truncate(3.7) + round(2.5) + ceiling(1.1) + floor(-1.5)", 6),
        ("X is 5 >> 1 + 1 << 2", 6),
        ("X is 6 /\\ 3 \\/ 8", 10),
        ("X is float(3)", 3.0),
        ("X is pi", 3.141592653589793),
    ],
)
def test_arithmetic(kb: KnowledgeBase, query: str, expected: object) -> None:
    value = one(kb, query)
    assert value == pytest.approx(expected) and type(value) is type(expected)


def test_arithmetic_comparisons_and_errors(kb: KnowledgeBase) -> None:
    assert kb.holds("1 < 2, 2 =< 2, 3 > 2.5, 3 >= 3, 1 =:= 1.0, 1 =\\= 2")
    assert not kb.holds("2 < 1")
    with pytest.raises(PrologInstantiationError):
        kb.holds("X is Y + 1")
    with pytest.raises(PrologEvaluationError):
        kb.holds("X is 1 // 0")
    with pytest.raises(PrologTypeError, match="foo/0"):
        kb.holds("X is foo + 1")


def test_unification_and_comparison(kb: KnowledgeBase) -> None:
    assert kb.holds("f(X, b) = f(a, Y), X == a, Y == b")
    assert kb.holds("a \\= b") and not kb.holds("X \\= b")
    assert kb.holds("f(X) \\== f(Y)") and kb.holds("X == X")
    assert not kb.holds("1 = 1.0") and kb.holds("1 == 1") and not kb.holds("1 == 1.0")
    assert kb.holds('1.0 @< 1, 1 @< a, a @< "s", "s" @< f(x), X @< 1')
    assert kb.holds("b @> a, f(a) @>= f(a), g(a) @> f(a, b) ; true")
    assert one(kb, "compare(X, 1, 2)") == "<" and one(kb, "compare(X, b, a)") == ">"


def test_type_tests(kb: KnowledgeBase) -> None:
    assert kb.holds("var(X), nonvar(a), \\+ bound(_), bound(1), atom(a), \\+ atom(1)")
    assert kb.holds('number(1.5), integer(3), \\+ integer(3.0), float(3.0), atomic("s")')
    assert kb.holds("compound(f(x)), \\+ compound(a), callable(a), callable(f(x)), \\+ callable(3)")
    assert kb.holds("is_list([1, 2]), \\+ is_list([1|_]), ground(f(a)), \\+ ground(f(_))")


def test_term_construction(kb: KnowledgeBase) -> None:
    assert kb.first("functor(f(a, b), N, A)") == {"N": "f", "A": 2}
    assert isinstance(one(kb, "functor(X, point, 3)"), Term)
    assert one(kb, "arg(2, f(a, b), X)") == "b"
    assert one(kb, "f(a, b) =.. X") == ["f", "a", "b"]
    assert one(kb, "X =.. [g, 1]") == Term("g", (1,))
    assert kb.holds("copy_term(f(X, X, Y), f(A, B, C)), A == B, A \\== C")


def test_between_succ_plus(kb: KnowledgeBase) -> None:
    assert [a["X"] for a in kb.query("between(1, 3, X)")] == [1, 2, 3]
    assert kb.holds("between(1, 3, 2)") and not kb.holds("between(1, 3, 5)")
    assert one(kb, "succ(X, 4)") == 3 and one(kb, "succ(3, X)") == 4
    assert not kb.holds("succ(X, 0)")
    assert one(kb, "plus(2, X, 5)") == 3


def test_all_solutions(kb: KnowledgeBase) -> None:
    assert one(kb, "findall(P, age(P, 31), X)") == ["ann", "cid"]
    assert one(kb, "findall(P, age(P, 99), X)") == []
    groups = [(a["A"], a["L"]) for a in kb.query("bagof(P, age(P, A), L)")]
    assert groups == [(25, ["bob"]), (31, ["ann", "cid"])]
    assert one(kb, "setof(A, P^age(P, A), X)") == [25, 31]
    assert one(kb, "setof(A-P, age(P, A), X)") == [
        Term("-", (25, "bob")),
        Term("-", (31, "ann")),
        Term("-", (31, "cid")),
    ]
    assert not kb.holds("bagof(P, age(P, 99), L)")
    assert kb.holds("forall(age(_, A), A > 20)") and not kb.holds("forall(age(_, A), A > 30)")


def test_aggregate_all(kb: KnowledgeBase) -> None:
    assert one(kb, "aggregate_all(count, age(_, _), X)") == 3
    assert one(kb, "aggregate_all(sum(A), age(_, A), X)") == 87
    assert one(kb, "aggregate_all(max(A), age(_, A), X)") == 31
    assert one(kb, "aggregate_all(min(A), age(_, A), X)") == 25
    assert one(kb, "aggregate_all(bag(A), age(_, A), X)") == [31, 25, 31]
    assert one(kb, "aggregate_all(set(A), age(_, A), X)") == [25, 31]
    assert one(kb, "aggregate_all(max(A, P), age(P, A), X)") == Term("max", (31, "ann"))
    assert not kb.holds("aggregate_all(max(A), age(_, A), 99)")
    assert one(kb, "aggregate_all(sum(A), fail, X)") == 0


def test_list_predicates(kb: KnowledgeBase) -> None:
    assert [a["X"] for a in kb.query("member(X, [a, b])")] == ["a", "b"]
    assert [a["X"] for a in kb.query("memberchk(X, [a, b])")] == ["a"]
    assert one(kb, "append(X, [c], [a, b, c])") == ["a", "b"]
    assert one(kb, "length([a, b, c], X)") == 3
    assert one(kb, "length(X, 2), X = [a | T], T = [b]") == ["a", "b"]
    assert not kb.holds("length(X, 2), X = [a]")
    assert [a["N"] for a in kb.query("length(L, N), N >= 2, !")] == [2]
    assert one(kb, "nth0(1, [a, b, c], X)") == "b" and one(kb, "nth1(1, [a, b, c], X)") == "a"
    assert [a["I"] for a in kb.query("nth1(I, [a, b, a], a)")] == [1, 3]
    assert one(kb, "last([a, b, c], X)") == "c"
    assert one(kb, "reverse([1, 2, 3], X)") == [3, 2, 1]
    assert one(kb, "msort([b, a, c, a], X)") == ["a", "a", "b", "c"]
    assert one(kb, "sort([b, a, c, a], X)") == ["a", "b", "c"]
    assert one(kb, "sort(0, @>=, [1, 3, 2, 3], X)") == [3, 3, 2, 1]
    assert one(kb, "sort(1, @<, [f(2, a), f(1, b), f(2, c)], X)") == [
        Term("f", (1, "b")),
        Term("f", (2, "a")),
    ]
    assert one(kb, "sum_list([1, 2, 3.5], X)") == 6.5
    assert one(kb, "max_list([1, 5, 3], X)") == 5 and one(kb, "min_list([4, 2, 8], X)") == 2
    assert not kb.holds("max_list([], X)")


def test_higher_order(kb: KnowledgeBase) -> None:
    assert kb.holds("maplist(integer, [1, 2])") and not kb.holds("maplist(integer, [1, a])")
    assert one(kb, "maplist(succ, [1, 2], X)") == [2, 3]
    assert one(kb, "maplist(plus, [1, 2], [10, 20], X)") == [11, 22]
    assert one(kb, "maplist(plus, [1], [2], [X])") == 3
    assert one(kb, "include(even, [1, 2, 3, 4], X)") == [2, 4]
    assert one(kb, "exclude(even, [1, 2, 3, 4], X)") == [1, 3]


def test_atoms_and_format(kb: KnowledgeBase) -> None:
    assert one(kb, "atom_concat(abc, def, X)") == "abcdef"
    assert [(a["X"], a["Y"]) for a in kb.query("atom_concat(X, Y, ab)")] == [
        ("", "ab"),
        ("a", "b"),
        ("ab", ""),
    ]
    assert one(kb, "atom_length(hello, X)") == 5
    assert one(kb, "format(atom(X), '~w is ~a at ~2f m, ~d items~n', [cup, red, 1.5, 3])") == (
        "cup is red at 1.50 m, 3 items\n"
    )
    assert one(kb, "format(atom(X), '~q ~w', ['A b', f(x, [1])])") == "'A b' f(x,[1])"
    assert one(kb, "format(atom(X), 'no args', [])") == "no args"
    assert one(kb, "atom_chars(X, [a, b])") == "ab" and one(kb, "atom_codes(ab, X)") == [97, 98]
    assert one(kb, "atom_number('3.5', X)") == 3.5
    assert one(kb, "atomic_list_concat([a, b, 1], '-', X)") == "a-b-1"
    assert one(kb, "atomic_list_concat(X, ',', 'a,b')") == ["a", "b"]
    assert one(kb, "upcase_atom(abc, X)") == "ABC"
    assert one(kb, 'X = "text"') == "text" and not kb.holds('"text" = text')

"""A compound in a clause head matches only a term of its own arity (checked by unpacking).

Clause code reads a head compound's arguments by unpacking them, and that unpacking is
the arity test: a same-named compound of another arity must fail that clause and fall
through to the next one, as it does for the same clauses declared dynamic (interpreted).
"""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase

CLAUSES = """
r(x, g(_, _), two).
r(x, g(_), one).
r(x, g, zero).
s(h(g(A, B)), A-B).
s(h(g(A)), A).
t(k, f(a, b), long).
t(k, f(a), short).
u([g(A, B)|_], A+B).
u([g(A)|_], A).
m(g(_, _), 1).
m(_, 2).
m(g(_, _), 3).
m(_, 4).
n(g(_, _), 1).
n(g(_, _), 2).
e(g(_, _), 1).
e(h(_), 2).
e(_, 3).
z(g(_, _), 1).
z(g(_), 2).
big(a1(_), 1).
big(a2(_), 2).
big(a3(_), 3).
big(a4(_), 4).
big(a5(_), 5).
big(a6(_), 6).
big(a7(_), 7).
big(_, 0).
"""

QUERIES = [
    ("r(x, g(1), W)", ["one"]),
    ("r(x, g(1, 2), W)", ["two"]),
    ("r(x, g(1, 2, 3), W)", []),
    ("r(x, g, W)", ["zero"]),
    ("s(h(g(1)), W)", ["1"]),
    ("s(h(g(1, 2)), W)", ["1-2"]),
    ("s(h(g), W)", []),
    ("t(k, f(a), W)", ["short"]),
    ("t(k, f(a, b), W)", ["long"]),
    ("t(k, f(a, b, c), W)", []),
    ("u([g(3)], W)", ["3"]),
    ("u([g(3, 4)], W)", ["3+4"]),
    ("m(g(x), W)", ["2", "4"]),  # the first-argument switch: one functor, by name only
    ("m(g(x, y), W)", ["1", "2", "3", "4"]),
    ("m(g, W)", ["2", "4"]),
    ("n(g(x), W)", []),
    ("n(g(x, y, z), W)", []),
    ("n(g(x, y), W)", ["1", "2"]),
    ("e(g(x), W)", ["3"]),  # several functors of distinct names: by name only
    ("e(h(x, y), W)", ["3"]),
    ("e(h(x), W)", ["2", "3"]),
    ("e(g(x, y), W)", ["1", "3"]),
    ("z(g(x), W)", ["2"]),  # one name, two arities: name and arity
    ("z(g(x, y), W)", ["1"]),
    ("big(a3(x, y), W)", ["0"]),  # past six functors, a table of names
    ("big(a3(x), W)", ["3", "0"]),
    ("big(a7(x), W)", ["7", "0"]),
]


def answers(kb: KnowledgeBase, query: str) -> list[object]:
    """The W of every answer, written out by format/3."""
    return [b["A"] for b in kb.query(f"{query}, format(atom(A), '~w', [W])")]


@pytest.mark.parametrize(("query", "expected"), QUERIES)
def test_head_compounds_of_another_arity_fall_through(query: str, expected: list[str]) -> None:
    static = KnowledgeBase()
    static.consult(CLAUSES)
    dynamic = KnowledgeBase()
    dynamic.consult(":- dynamic r/3, s/2, t/3, u/2, m/2, n/2, e/2, z/2, big/2.\n" + CLAUSES)
    for _ in range(3):  # interpreted at first, compiled from the second call on
        assert answers(static, query) == expected
    assert answers(dynamic, query) == expected

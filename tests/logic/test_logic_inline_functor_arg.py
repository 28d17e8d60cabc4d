"""arg/3 and functor/3 compiled inline in clause bodies give the built-ins' answers and errors.

Each goal runs six times first, so that its clause is compiled (inline code) before the
checked call; the expected results were checked against `swipl` 9.0.4.
"""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase

PROGRAM = """
a1(N, T, A) :- arg(N, T, A).
a2(T, A) :- arg(2, T, A), A == b.
a3(T, F, N) :- functor(T, F, N).
a5(T, N) :- functor(T, f, N), arg(1, T, x).
a7(T, F) :- functor(T, F, 2), arg(2, T, z).
a8(F, N, A) :- functor(X, F, N), functor(X, _, A).
a9(F, N) :- functor(X, F, N), X =.. [_|As], sort(As, S), length(S, N), \\+ \\+ S = As.
probe(G, R) :-
    forall(between(1, 6, _), ignore(catch(\\+ \\+ G, _, true))),
    catch((G -> R = G ; R = false), error(E, _), R = E).
"""


@pytest.fixture(scope="module")
def kb() -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult(PROGRAM)
    return kb


@pytest.mark.parametrize(
    ("goal", "expected"),
    [
        ("a1(1, f(a, b), _)", "a1(1,f(a,b),a)"),
        ("a1(3, f(a, b), _)", "false"),
        ("a1(0, f(a), _)", "false"),
        ("a1(-1, f(a), _)", "domain_error(not_less_than_zero,-1)"),
        ("a1(x, f(a), _)", "type_error(integer,x)"),
        ("a1(1, _, _)", "instantiation_error"),
        ("a1(1, atom, _)", "type_error(compound,atom)"),
        ("a2(f(a, c), _)", "false"),
        ("a3(f(a, b), _, _)", "a3(f(a,b),f,2)"),
        ("a3(1.5, _, _)", "a3(1.5,1.5,0)"),
        ("a3(_, _, _)", "instantiation_error"),
        ("a3(_, foo, 0)", "a3(foo,foo,0)"),
        ("a3(_, foo, -1)", "domain_error(not_less_than_zero,-1)"),
        ("a3(_, foo, a)", "type_error(integer,a)"),
        ("a3(_, f(x), 1)", "type_error(atomic,f(x))"),
        ("a3(_, 1, 2)", "type_error(atom,1)"),
        ("a3(f(a), f, 2)", "false"),
        ("a5(_, 1)", "a5(f(x),1)"),
        ("a7(h(1, z), _)", "a7(h(1,z),h)"),
        ("a7(h(1, y), _)", "false"),
        ("a8(g, 3, _)", "a8(g,3,3)"),
        ("a8(foo, 0, _)", "a8(foo,0,0)"),
        ("a8(1.5, 0, _)", "a8(1.5,0,0)"),
        ("a8(_, 2, _)", "instantiation_error"),
        ("a8(foo, -1, _)", "domain_error(not_less_than_zero,-1)"),
        ("a8(foo, a, _)", "type_error(integer,a)"),
        ("a8(f(x), 1, _)", "type_error(atomic,f(x))"),
        ("a8(1, 2, _)", "type_error(atom,1)"),
        ("a9(g, 3)", "a9(g,3)"),
        ("a9(g, 5)", "a9(g,5)"),
    ],
)
def test_inline_arg_and_functor(kb: KnowledgeBase, goal: str, expected: str) -> None:
    answer = kb.first(f"probe({goal}, R), format(atom(T), '~q', [R])")
    assert answer is not None and answer["T"] == expected

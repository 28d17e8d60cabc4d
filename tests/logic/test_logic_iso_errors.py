"""ISO edge cases: every error is a catchable `error(Formal, _)`, answers are exact."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.logic import KnowledgeBase, PrologResourceError, Term
from robocram.logic.terms import format_term

# goal -> the formal error term ISO specifies (caught with catch/3)
ERRORS = [
    ("char_code(ab, _)", "type_error(character,ab)"),
    ("char_code(_, -2)", "representation_error(character_code)"),
    ("char_code(_, _)", "instantiation_error"),
    ("char_code(_, a)", "type_error(integer,a)"),
    ("atom_chars(_, [a, _, c])", "instantiation_error"),
    ("atom_chars(_, [a, f(b)])", "type_error(character,f(b))"),
    ("atom_codes(_, [0'a, x])", "type_error(integer,x)"),
    ("atom_chars(_, _)", "instantiation_error"),
    ("number_chars(a, _)", "type_error(number,a)"),
    ("number_chars(_, ['1', a])", "syntax_error(illegal_number)"),
    ("number_codes(_, [0'1, 0' , 0'2])", "syntax_error(illegal_number)"),
    ("functor(_, foo, -1)", "domain_error(not_less_than_zero,-1)"),
    ("functor(_, foo(a), 1)", "type_error(atomic,foo(a))"),
    ("functor(_, _, 1)", "instantiation_error"),
    ("arg(-3, foo(a, b), _)", "domain_error(not_less_than_zero,-3)"),
    ("arg(1, _, _)", "instantiation_error"),
    ("arg(1, atom, _)", "type_error(compound,atom)"),
    ("call((fail, 1))", "type_error(callable,(fail,1))"),
    ("call((write(x) ; 1))", "type_error(callable,(write(x);1))"),
    ("sub_atom(_, _, _, _, _)", "instantiation_error"),
    ("sub_atom(abc, -1, _, _, _)", "domain_error(not_less_than_zero,-1)"),
]


@pytest.mark.parametrize(("goal", "formal"), ERRORS)
def test_errors_are_iso_and_catchable(goal: str, formal: str) -> None:
    answer = KnowledgeBase().first(f"catch(({goal}), error(F, _), true), nonvar(F)")
    assert answer is not None, f"{goal} raised no error"
    assert format_term(answer["F"], quoted=True) == formal


# goal -> its answers (as Python values), in order
ANSWERS = [
    ("number_chars(N, [' ', '1', '2'])", [{"N": 12}]),
    ("number_codes(N, [0'0, 0'x, 0'1, 0'F])", [{"N": 31}]),
    ("number_chars(N, ['-', '2', '.', '5'])", [{"N": -2.5}]),
    ("atom_chars(X, [a, b])", [{"X": "ab"}]),
    ("atom_chars(abc, L)", [{"L": ["a", "b", "c"]}]),
    ("char_code(C, 0'z)", [{"C": "z"}]),
    ("sub_atom(abcab, B, 2, A, ab)", [{"B": 0, "A": 3}, {"B": 3, "A": 0}]),
    (
        "sub_atom(abc, B, L, 0, S)",
        [
            {"B": 0, "L": 3, "S": "abc"},
            {"B": 1, "L": 2, "S": "bc"},
            {"B": 2, "L": 1, "S": "c"},
            {"B": 3, "L": 0, "S": ""},
        ],
    ),
    ("sub_atom(abc, 1, 1, A, S)", [{"A": 1, "S": "b"}]),
    (
        "bagof(_X, member(_X-K, [1-a, 2-b, 3-a]), L)",
        [{"K": "a", "L": [1, 3]}, {"K": "b", "L": [2]}],
    ),
    ("bagof(_X, (_X = _Y ; _X = _Z), _L), _L == [_Y, _Z]", [{}]),
    ("setof(_X, (_X = _Y ; _X = _Z), _L), (_L == [_Y, _Z] ; _L == [_Z, _Y])", [{}]),
    ("setof(_X, member(_X, [c, a, b, a]), L)", [{"L": ["a", "b", "c"]}]),
    ("_X = f(_X), _Y = f(_Y), _X = _Y, ground(_X)", [{}]),
    ("_X = f(_X, a), _Y = f(_Y, a), _X = _Y", [{}]),
    ("_X = f(_X), \\+ acyclic_term(_X), acyclic_term(f(_W, _W))", [{}]),
]


@pytest.mark.parametrize(("goal", "answers"), ANSWERS)
def test_answers_are_exact(goal: str, answers: list[dict[str, object]]) -> None:
    assert list(KnowledgeBase().query(goal)) == answers


def test_cyclic_answer_is_a_resource_error_not_a_python_crash() -> None:
    with pytest.raises(PrologResourceError, match="cyclic or nested too deeply"):
        KnowledgeBase().first("X = f(X)")


def test_host_exceptions_are_catchable_and_reraised_when_uncaught() -> None:
    kb = KnowledgeBase()

    @kb.predicate("boom", 1)
    def boom(x: object) -> Iterator[None]:
        raise KeyError(x)
        yield None

    kb.register_function("div", lambda a, b: a / b)
    answer = kb.first("catch(boom(1), error(python_error(C, _), _), true)")
    assert answer == {"C": "KeyError"}
    answer = kb.first("catch(py_fun(div, 1, 0, _), error(python_error(C, _), _), true)")
    assert answer == {"C": "ZeroDivisionError"}
    with pytest.raises(KeyError):
        kb.first("boom(2)")
    with pytest.raises(ZeroDivisionError):
        kb.first("findall(R, py_fun(div, 1, 0, R), _)")


def test_deep_terms_copy_and_other_limits_are_resource_errors() -> None:
    kb = KnowledgeBase()
    kb.consult(
        "nest(0, z) :- !.\nnest(N, f(T)) :- M is N - 1, nest(M, T).\n"
        "depth(z, 0).\ndepth(f(T), N) :- depth(T, M), N is M + 1."
    )
    deep = "nest(5000, _T), nest(5000, _T2)"
    # copy_term and findall copy a term of any depth.
    assert kb.first(f"{deep}, copy_term(_T, _C), findall(_T, true, [_F]), depth(_F, N)") == {
        "N": 5000
    }
    # What still recurses in Python ends in a catchable resource error, never a crash.
    answer = kb.first(f"{deep}, catch(compare(_, _T, _T2), error(E, _), true)")
    assert answer == {"E": Term("resource_error", ("term_depth",))}


def test_deep_answers_convert_and_cyclic_ones_raise() -> None:
    kb = KnowledgeBase()
    kb.consult("nest(0, z) :- !.\nnest(N, f(T)) :- M is N - 1, nest(M, T).")
    term = kb.first("nest(3000, T)")["T"]  # type: ignore[index]
    depth = 0
    while isinstance(term, Term):
        term, depth = term.args[0], depth + 1
    assert (depth, term) == (3000, "z")
    with pytest.raises(PrologResourceError):
        kb.first("X = f(X, Y), Y = g(X)")

"""Built-ins that walk a term raise resource_error(term_depth) on a cyclic term.

Before, copy_term, findall, assertz, term_variables, length and the text built-ins looped
on `X = f(X)` or `L = [a|L]`, eating memory; unification itself handles such terms.
"""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase, PrologResourceError

GOALS = [
    "copy_term(X, _)",
    "copy_term(g(X), _)",
    "copy_term(L, _)",
    "findall(X, true, _)",
    "findall(L, true, _)",
    "assertz(p(X))",
    "asserta(p(L))",
    "term_variables(X, _)",
    "setof(Y, member(Y, [X]), _)",
    "bagof(Y, member(Y, [L]), _)",
    "throw(X)",
    "length(L, _)",
    "length(L, 3)",
    "msort(L, _)",
    "sort(0, @>=, L, _)",
    "keysort(L, _)",
    "sum_list(L, _)",
    "atom_codes(_, L)",
    "atom_chars(_, L)",
    "number_codes(_, L)",
    "atomic_list_concat(L, _)",
    "compare(_, X, X)",
    "msort([X, X], _)",
    "format(atom(_), '~w', [X])",
    "format(atom(_), '~w', [L])",
    "write_canonical(X)",
]


@pytest.fixture(scope="module")
def kb() -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult("""
        :- dynamic p/1.
        on_cyclic(G, E) :-
            X = f(X, a), L = [a|L],
            catch((call(G, X, L), E = none), error(E, _), true).
    """)
    return kb


@pytest.mark.parametrize("goal", GOALS)
def test_a_cyclic_term_gives_a_resource_error(kb: KnowledgeBase, goal: str) -> None:
    kb.consult(f"probe(X, L) :- {goal}.")
    try:
        found = kb.holds(
            "on_cyclic(probe, E), E == resource_error(term_depth)", max_inferences=10**5
        )
    finally:
        kb.holds("retractall(probe(_, _))")
    assert found


def test_is_list_fails_on_a_cyclic_list() -> None:
    assert not KnowledgeBase().holds("L = [a|L], is_list(L)")


def test_the_escaped_error_is_typed() -> None:
    kb = KnowledgeBase()
    with pytest.raises(PrologResourceError) as err:
        kb.holds("X = f(X), copy_term(X, _)")
    assert err.value.resource == "term_depth"


def test_long_and_deep_acyclic_terms_still_copy() -> None:
    kb = KnowledgeBase()
    kb.consult("nest(0, x) :- !.\nnest(N, f(T)) :- M is N - 1, nest(M, T).")
    answer = kb.first("numlist(1, 100000, L), copy_term(L, C), length(C, N)")
    assert answer is not None and answer["N"] == 100_000
    assert kb.holds("nest(20000, T), copy_term(T, C), term_variables(C, []), C = f(f(_))")

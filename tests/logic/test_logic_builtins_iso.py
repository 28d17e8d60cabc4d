"""Built-ins added for ISO conformance: flags, term output, reading from text, database."""

from __future__ import annotations

import itertools

import pytest

from robocram.logic import KnowledgeBase, PrologResourceError, UnknownPredicateError
from robocram.logic.arith import MAX_INTEGER_BITS


def _formal(kb: KnowledgeBase, goal: str) -> str:
    answer = kb.first(f"catch(({goal}), error(F, _), true), nonvar(F), term_to_atom(F, A)")
    assert answer is not None, f"{goal} raised no error"
    return str(answer["A"])


def test_double_quotes_flag_applies_to_later_clauses_and_queries() -> None:
    kb = KnowledgeBase()
    assert kb.first('X = "ab", string(X)') is not None  # default: strings, as in SWI
    kb.consult(':- set_prolog_flag(double_quotes, codes).\nw("ab").')
    assert kb.first("w(X)") == {"X": [97, 98]}
    assert kb.first('X = "ab"') == {"X": [97, 98]}
    kb.holds("set_prolog_flag(double_quotes, chars)")
    assert kb.first('X = "ab"') == {"X": ["a", "b"]}
    kb.holds("set_prolog_flag(double_quotes, atom)")
    assert kb.first('X = "ab", atom(X)') == {"X": "ab"}


def test_flag_errors_and_read_only_flags() -> None:
    kb = KnowledgeBase()
    assert kb.first("current_prolog_flag(bounded, B)") == {"B": "false"}
    assert kb.first("current_prolog_flag(max_integer_bits, N)") == {"N": MAX_INTEGER_BITS}
    assert _formal(kb, "set_prolog_flag(bounded, true)") == "permission_error(modify,flag,bounded)"
    assert _formal(kb, "set_prolog_flag(nope, 1)") == "domain_error(prolog_flag,nope)"
    assert (
        _formal(kb, "set_prolog_flag(unknown, maybe)") == "domain_error(flag_value,unknown+maybe)"
    )
    assert _formal(kb, "set_prolog_flag(occurs_check, maybe)") == (
        "domain_error(flag_value,occurs_check+maybe)"
    )
    assert _formal(kb, "set_prolog_flag(_, true)") == "instantiation_error"


def test_unknown_flag_error_fail_warning(capsys: pytest.CaptureFixture[str]) -> None:
    kb = KnowledgeBase()
    with pytest.raises(UnknownPredicateError):
        kb.holds("nothing_here(1)")
    kb.holds("set_prolog_flag(unknown, fail)")
    assert not kb.holds("nothing_here(1)")
    kb.holds("set_prolog_flag(unknown, warning)")
    assert not kb.holds("nothing_here(1)")
    assert "unknown procedure nothing_here/1" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("goal", "text"),
    [
        ("writeq('hello world'-[a, 'B'])", "'hello world'-[a,'B']"),
        ("print(f('A', \"s\"))", "f('A',\"s\")"),
        ("write_canonical(1 + a * 'X')", "+(1,*(a,'X'))"),
        ("write_term(f('$VAR'(1), 'x y'), [quoted(true), numbervars(true)])", "f(B,'x y')"),
        ("write_term(1 - 2, [ignore_ops(true)])", "-(1,2)"),
        ("write(user_error, x), write(- (1)), write(' '), write(-1)", "-(1) -1"),
        ("X is 2 ** 200, write(X)", str(2**200)),
        ("nl", "\n"),
    ],
)
def test_term_output(goal: str, text: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert KnowledgeBase().holds(goal)
    assert capsys.readouterr().out == text


def test_write_term_option_errors() -> None:
    kb = KnowledgeBase()
    assert _formal(kb, "write_term(a, [colour(red)])") == "domain_error(write_option,colour(red))"
    assert (
        _formal(kb, "write_term(a, [quoted(maybe)])") == "domain_error(write_option,quoted(maybe))"
    )
    assert _formal(kb, "write_term(a, _)") == "instantiation_error"
    assert _formal(kb, "write(nowhere, a)") == "existence_error(stream,nowhere)"


def test_reading_terms_from_text() -> None:
    kb = KnowledgeBase()
    answer = kb.first("read_term_from_atom('foo(X, Y, X)', T, []), T = foo(1, 2, Z)")
    assert answer is not None and answer["Z"] == 1
    assert kb.first('term_string(T, "g(a, [1])")') == {"T": kb.first("T = g(a, [1])")["T"]}  # type: ignore[index]
    assert kb.first("term_string(f(x, 'A'), S)") == {"S": "f(x,'A')"}
    assert kb.first("term_to_atom(T, 'p(1) :- q'), T = (H :- B)") is not None
    assert _formal(kb, "term_to_atom(_, 'foo(')").startswith("syntax_error(")
    assert _formal(kb, "read_term_from_atom(_, _, [])") == "instantiation_error"


def test_database_builtins() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic counter/1.\ncounter(0).\nstatic_fact(1).")
    found = {a["P"] for a in kb.query("current_predicate(P)")}
    assert {"counter/1", "static_fact/1", "append/3"} <= {f"{t.args[0]}/{t.args[1]}" for t in found}
    assert kb.holds("current_predicate(counter/1)")
    assert not kb.holds("current_predicate(atom_length/2)")  # built-ins are not listed (ISO)
    assert kb.holds("abolish(counter/1)")
    assert not kb.holds("current_predicate(counter/1)")
    assert _formal(kb, "counter(_)") == "existence_error(procedure,counter/1)"
    assert _formal(kb, "abolish(static_fact/1)") == (
        "permission_error(modify,static_procedure,static_fact/1)"
    )
    assert _formal(kb, "abolish(_)") == "instantiation_error"
    assert kb.first("repeat, X = 1") == {"X": 1}
    assert len(list(itertools.islice(kb.query("repeat"), 5))) == 5  # as many as asked
    assert kb.first("findall(N, (between(1, 3, N), once(repeat)), L)")["L"] == [1, 2, 3]  # type: ignore[index]


@pytest.mark.parametrize(
    ("goal", "holds"),
    [
        ("unify_with_occurs_check(X, f(Y))", True),
        ("unify_with_occurs_check(X, f(X))", False),
        ("unify_with_occurs_check(f(X, Y), f(Y, g(X)))", False),
        ("subsumes_term(f(_), f(a))", True),
        ("subsumes_term(f(a), f(_))", False),
        ("subsumes_term(f(X, X), f(Y, Z))", False),
        ("subsumes_term(f(X, Y), f(Z, Z))", True),
        ("subsumes_term(g(X), g(f(X)))", False),
    ],
)
def test_occurs_check_and_subsumption(goal: str, holds: bool) -> None:
    assert KnowledgeBase().holds(goal) is holds


def test_huge_integers_are_capped_and_printable() -> None:
    kb = KnowledgeBase()
    assert _formal(kb, "X is 1 << 10**11") == "resource_error(memory)"
    assert _formal(kb, "X is 2 ** (2 ** 40)") == "resource_error(memory)"
    answer = kb.first('X is 2 ** 100000, format(atom(A), "~d", [X]), atom_length(A, N)')
    assert answer is not None and answer["N"] == 30103  # digits of 2**100000
    with pytest.raises(PrologResourceError):
        kb.holds("X is 7 ^ (10 ** 9)")

"""The knowledge base's generation: every change of clauses, predicates or syntax counts."""

from __future__ import annotations

from collections.abc import Iterator

from robocram.logic import KnowledgeBase


def _kb() -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult(":- dynamic(fact/1).\nfact(1).\nrule(X) :- fact(X).", group="g")
    return kb


def test_every_way_of_changing_clauses_changes_the_generation() -> None:
    kb = _kb()
    changes = [
        lambda: kb.consult("rule(X) :- fact(X), X > 0.", group="g"),
        lambda: kb.assertz("fact(2)"),
        lambda: kb.retract("fact(2)"),
        lambda: kb.holds("assertz(fact(3))"),
        lambda: kb.holds("retract(fact(3))"),
        lambda: kb.holds("asserta(fact(0))"),
        lambda: kb.holds("retractall(fact(0))"),
        lambda: kb.holds("dynamic(other/2)"),
        lambda: kb.holds("abolish(other/2)"),
        lambda: kb.holds("op(700, xfx, ===>)"),
        lambda: kb.holds("set_prolog_flag(unknown, fail)"),
        lambda: kb.add_fact_group("h", ["h(1)."]),
        lambda: kb.declare_dynamic(("d", 1)),
        lambda: kb.add_predicate("py", 1, _one),
        lambda: kb.register_function("f", abs),
    ]
    for change in changes:
        before = kb.generation
        change()
        assert kb.generation != before, change


def test_queries_and_loading_a_group_again_unchanged_keep_the_generation() -> None:
    kb = _kb()
    text = "colour(red).\ncolour(green).\nwarm(C) :- colour(C), C == red."
    kb.consult(text, group="colours")
    before = kb.generation
    for _ in range(4):  # enough calls to compile the procedures
        assert [a["C"] for a in kb.query("warm(C)")] == ["red"]
    kb.consult(text, group="colours")
    assert kb.generation == before
    kb.consult(text + "\ncolour(blue).", group="colours")
    assert kb.generation != before
    assert [a["C"] for a in kb.query("colour(C)")] == ["red", "green", "blue"]


def test_a_group_loaded_again_after_another_groups_clauses_moves_behind_them() -> None:
    kb = KnowledgeBase()
    kb.consult("p(a).", group="first", extendable=["p/1"])
    kb.consult("p(b).", group="second")
    kb.consult("p(a).", group="first", extendable=["p/1"])
    assert [a["X"] for a in kb.query("p(X)")] == ["b", "a"]
    before = kb.generation
    kb.consult("p(a).", group="first", extendable=["p/1"])
    assert kb.generation == before
    assert [a["X"] for a in kb.query("p(X)")] == ["b", "a"]


def test_a_text_read_again_after_an_operator_changed_reads_the_new_way() -> None:
    kb = KnowledgeBase()
    text = "t(X) :- X = (a ===> b)."
    kb.consult(":- op(700, xfx, ===>).", group="ops")
    kb.consult(text, group="t")
    assert kb.first("t(X), X = (L ===> R)") is not None
    kb.holds("op(0, xfx, ===>)")
    kb.holds("op(200, xfy, ===>)")
    kb.consult(text, group="t")
    assert kb.first("t(X), X =.. [Op, a, b]")["Op"] == "===>"


def test_a_retracted_clause_of_a_dynamic_group_comes_back_when_it_is_loaded_again() -> None:
    kb = KnowledgeBase()
    kb.declare_dynamic(("f", 1))
    kb.consult("f(1).\nf(2).", group="fs")
    assert kb.retract("f(1)")
    kb.consult("f(1).\nf(2).", group="fs")
    assert [a["X"] for a in kb.query("f(X)")] == [1, 2]


def _one(x: object) -> Iterator[tuple[object]]:
    yield (1,)


def test_defines_answers_as_the_list_of_predicates_does() -> None:
    kb = _kb()
    kb.add_predicate("py", 1, _one)
    listed = set(kb.predicates())
    for indicator in ["fact/1", "rule/1", "py/1", "rule/2", "member/2", "atom/1", "x", "x/y"]:
        assert kb.defines(indicator) == (indicator in listed), indicator

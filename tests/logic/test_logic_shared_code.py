"""Generated code shared by knowledge bases reading the same texts (logic/shared_code.py)."""

from __future__ import annotations

import gc
import weakref

import pytest

from robocram.logic import KnowledgeBase
from robocram.logic import procedure as procedure_module
from robocram.logic.direct_calls import LEVELS
from robocram.logic.predicate import WARM_CALLS
from robocram.logic.procedure import MAX_CLAUSES
from robocram.logic.shared_code import SharedProcedures
from robocram.logic.terms import Term

CALLER = "p(X) :- q(X, Y), Y > 0. r(X) :- p(X)."


def _kb(callee: str) -> KnowledgeBase:
    kb = KnowledgeBase()
    kb.consult(CALLER, group="caller")
    kb.consult(callee, group="callee")
    return kb


def _answers(kb: KnowledgeBase, query: str = "r(X)") -> list[object]:
    """The answers of `query`, asked until every predicate in it is compiled."""
    found = [[a["X"] for a in kb.query(query)] for _ in range(WARM_CALLS + 2)]
    assert all(f == found[0] for f in found)
    return found[0]


@pytest.fixture
def generated(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The names of the predicates whose procedure code is generated (not shared)."""
    names: list[str] = []
    write = procedure_module._ProcWriter.procedure

    def counted(self: procedure_module._ProcWriter, branches: object) -> None:
        names.append(self.clauses[0].name)
        write(self, branches)  # type: ignore[arg-type]

    monkeypatch.setattr(procedure_module._ProcWriter, "procedure", counted)
    monkeypatch.setattr(procedure_module, "SHARED_PROCEDURES", SharedProcedures())
    return names


def test_same_texts_share_the_code_and_bind_their_own_callees(generated: list[str]) -> None:
    # q has two clauses: p calls its procedure directly, the one of p's own knowledge base
    first = _kb("q(a, 1). q(b, 2).")
    assert _answers(first) == ["a", "b"]
    made = sorted(generated)
    assert made == ["p", "q", "r"]
    second = _kb("q(a, 1). q(b, 2).")
    assert _answers(second) == ["a", "b"]
    assert sorted(generated) == made  # nothing generated again
    p1, p2 = first._preds[("p", 1)].proc, second._preds[("p", 1)].proc
    assert p1 is not None and p2 is not None and p1 is not p2
    assert p2.__globals__["k0"] is not first  # constants bound to the second KB
    assert second in p2.__globals__.values() and first not in p2.__globals__.values()
    assert LEVELS[p2] == LEVELS[p1] == 1


def test_another_callee_is_called_not_the_first_knowledge_bases(generated: list[str]) -> None:
    assert _answers(_kb("q(a, 1). q(b, 2).")) == ["a", "b"]
    other = _kb("q(c, 3). q(d, 0). q(e, 4).")
    assert _answers(other) == ["c", "e"]
    assert generated.count("p") == 1  # p's code was shared, bound to other's q


def test_another_inlined_clause_generates_the_code_again(generated: list[str]) -> None:
    # a one-clause q is compiled into p: a different clause must not be reused
    assert _answers(_kb("q(a, 1).")) == ["a"]
    assert _answers(_kb("q(b, 2).")) == ["b"]
    assert _answers(_kb("q(c, 0).")) == []
    assert generated.count("p") == 3
    assert _answers(_kb("q(b, 2).")) == ["b"]  # the same text again: shared
    assert _answers(_kb("q(a, 1).")) == ["a"]
    assert generated.count("p") == 3


def test_assert_and_retract_change_the_answers_of_shared_code() -> None:
    assert _answers(_kb("q(a, 1). q(b, 2).")) == ["a", "b"]
    kb = KnowledgeBase()
    kb.consult(CALLER, group="caller")
    kb.consult(":- dynamic(q/2).\nq(a, 1).\nq(b, 2).", group="callee")
    assert _answers(kb) == ["a", "b"]
    kb.assertz("q(c, 5)")
    assert _answers(kb) == ["a", "b", "c"]
    assert kb.retract("q(a, 1)")
    assert _answers(kb) == ["b", "c"]
    kb.assertz("q(d, -1)")
    assert _answers(kb) == ["b", "c"]


def test_a_consulted_callee_changes_the_answers_of_shared_code(generated: list[str]) -> None:
    assert _answers(_kb("q(a, 1). q(b, 2).")) == ["a", "b"]
    kb = _kb("q(a, 1). q(b, 2).")
    assert _answers(kb) == ["a", "b"]
    assert generated.count("p") == 1
    kb.consult("q(z, 7). q(y, 8).", group="callee")  # replaces q: a new generation
    assert _answers(kb) == ["z", "y"]
    kb.consult("q(w, 9).", group="callee")  # one clause now: compiled into p
    assert _answers(kb) == ["w"]


def test_a_shared_clause_function_answers_for_its_own_knowledge_base() -> None:
    text = "s(X, Z) :- Z is X * 2 + 1."
    kbs = [KnowledgeBase() for _ in range(2)]
    for kb in kbs:
        kb.consult(text, group="s")
    for kb, x in zip(kbs, (3, 10), strict=True):
        got = [[a["Z"] for a in kb.query("s(X, Z)", X=x)] for _ in range(WARM_CALLS + 2)]
        assert got == [[2 * x + 1]] * (WARM_CALLS + 2)
    runs = [kb._preds[("s", 2)].clauses[0].run for kb in kbs]
    assert runs[0] is not None and runs[0] is runs[1]  # one function for both


def test_facts_made_afresh_share_code_by_content_with_types_kept(generated: list[str]) -> None:
    def facts_kb(first: object) -> KnowledgeBase:
        kb = KnowledgeBase()  # facts as a robot description adds them: new terms each time
        kb.add_fact_group("facts", [Term("f", (first, "a")), Term("f", (2, "b"))])
        return kb

    assert _answers(facts_kb(1), "f(1, X)") == ["a"]
    assert _answers(facts_kb(1), "f(1, X)") == ["a"]
    assert generated.count("f") == 1  # the second knowledge base's facts: the same content
    assert _answers(facts_kb(1.0), "f(1, X)") == []  # 1.0 is not 1 in Prolog
    assert _answers(facts_kb(1.0), "f(1.0, X)") == ["a"]
    assert _answers(facts_kb(True), "f(1, X)") == []  # a Python object stands for itself
    assert generated.count("f") == 3


def test_clause_functions_of_facts_made_afresh_are_shared_by_content() -> None:
    many = MAX_CLAUSES + 6  # run clause by clause: each clause's own function

    def facts_kb(scale: object) -> KnowledgeBase:
        kb = KnowledgeBase()
        kb.add_fact_group("facts", [Term("g", (i, Term("v", (i, scale)))) for i in range(many)])
        return kb

    kbs = [facts_kb(1), facts_kb(1), facts_kb(1.0)]
    for kb in kbs:
        for _ in range(WARM_CALLS + 2):
            assert [a["X"] for a in kb.query("g(I, v(I, X)), I >= 68")] in ([1, 1], [1.0, 1.0])
    assert [a["I"] for a in kbs[2].query("g(I, v(I, 1))")] == []  # 1.0 kept apart from 1
    runs = [kb._preds[("g", 2)].clauses[69].run for kb in kbs]
    assert runs[0] is not None and runs[0] is runs[1] and runs[2] is not runs[0]


def test_kept_code_holds_no_knowledge_base(generated: list[str]) -> None:
    kb = _kb("q(a, 1). q(b, 2).")
    assert _answers(kb) == ["a", "b"]
    assert sorted(generated) == ["p", "q", "r"]  # kept from this knowledge base
    gone = weakref.ref(kb)
    del kb
    gc.collect()
    assert gone() is None  # only its procedures held it; the kept code binds it per use

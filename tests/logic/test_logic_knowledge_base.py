"""Knowledge bases: fact groups, dynamic predicates, Python predicates, queries, errors."""

from __future__ import annotations

import threading
import tracemalloc
from collections.abc import Iterator

import pytest

from robocram.logic import (
    FactGroupError,
    KnowledgeBase,
    PrologError,
    PrologPermissionError,
    PrologSyntaxError,
    Term,
    UnknownPredicateError,
    Var,
    current_kb,
    using_kb,
)


def test_fact_group_reload_replaces_its_clauses() -> None:
    kb = KnowledgeBase()
    kb.consult("color(red). color(green).", group="colors")
    kb.consult("color(blue).", group="colors")
    assert [a["C"] for a in kb.query("color(C)")] == ["blue"]


def test_foreign_group_needs_extendable_declaration() -> None:
    kb = KnowledgeBase()
    kb.consult("robot_tool_frame(_, _, _) :- fail.", group="interface")
    with pytest.raises(FactGroupError) as info:
        kb.consult("robot_tool_frame(pr2, left, l_tool).", group="pr2_facts")
    assert "robot_tool_frame/3" in str(info.value) and "interface" in str(info.value)
    kb.consult(
        "robot_tool_frame(pr2, left, l_tool).", group="pr2", extendable=["robot_tool_frame/3"]
    )
    kb.consult(
        "robot_tool_frame(hsrb, arm, hand).", group="hsrb", extendable=["robot_tool_frame/3"]
    )
    assert kb.first("robot_tool_frame(hsrb, A, F)") == {"A": "arm", "F": "hand"}
    kb.consult("", group="pr2")
    assert kb.first("robot_tool_frame(pr2, _, F)") is None
    assert kb.first("robot_tool_frame(hsrb, _, F)") == {"F": "hand"}


def test_builtins_cannot_be_redefined() -> None:
    kb = KnowledgeBase()
    with pytest.raises(PrologPermissionError, match="atom_length/2 is a built-in"):
        kb.consult("atom_length(a, b).")
    with pytest.raises(PrologPermissionError):
        kb.assertz("atom_length(a, b)")
    assert kb.first("atom_length(abc, N)") == {"N": 3}


def test_dynamic_assert_retract() -> None:
    kb = KnowledgeBase()
    kb.consult(":- dynamic counter/1.\ncounter(0).")
    assert kb.holds("retract(counter(N)), M is N + 1, assertz(counter(M))")
    assert kb.first("counter(X)") == {"X": 1}
    kb.assertz("seen(cup)")
    kb.asserta(Term("seen", ("plate",)))
    assert [a["X"] for a in kb.query("seen(X)")] == ["plate", "cup"]
    assert kb.retract("seen(cup)") and not kb.retract("seen(cup)")
    assert kb.holds("retractall(seen(_)), \\+ seen(_)")
    kb.consult("static_fact(1).")
    with pytest.raises(PrologPermissionError, match="dynamic"):
        kb.holds("assertz(static_fact(2))")


def test_query_bindings_are_python_objects_unified_by_identity_or_eq() -> None:
    class World:
        pass

    world, mug = World(), {"name": "mug"}
    kb = KnowledgeBase()
    kb.consult("visible(W, camera, O) :- holds_object(W, O).")
    kb.add_predicate("holds_object", 2, lambda w, o: iter([None]) if w is world else iter([]))
    assert kb.holds("visible(W, R, O)", W=world, O=mug)
    assert kb.first("visible(W, R, O)", W=world, O=mug) == {"R": "camera"}
    assert kb.first("X = Y", Y=mug)["X"] is mug  # type: ignore[index]
    assert kb.first('X = [1, f(a, 2.5), "str", true]') == {
        "X": [1, Term("f", ("a", 2.5)), "str", "true"]
    }
    assert kb.holds("X == true", X=True) and kb.holds("X == 3", X=3)
    assert isinstance(kb.first("X = Y")["X"], Var)  # type: ignore[index]
    with pytest.raises(PrologError, match="names no variable"):
        kb.first("p(X)", Y=1)


def test_python_predicate_runs_before_clauses_and_binds_unbound_arguments() -> None:
    kb = KnowledgeBase()
    kb.consult("near(kitchen, fridge).")
    seen: list[object] = []

    @kb.predicate("near", 2)
    def near(room: object, thing: object) -> Iterator[tuple[object, object] | None]:
        seen.append((room, type(thing).__name__))
        yield ("kitchen", "sink")
        yield ("hall", "door")

    assert [(a["R"], a["T"]) for a in kb.query("near(R, T)")] == [
        ("kitchen", "sink"),
        ("hall", "door"),
        ("kitchen", "fridge"),
    ]
    assert [a["T"] for a in kb.query("near(kitchen, T)")] == ["sink", "fridge"]
    assert seen[0][1] == "Var" and seen[1] == ("kitchen", "Var")


def test_python_predicate_exception_propagates_unchanged() -> None:
    kb = KnowledgeBase()
    boom = RuntimeError("sensor offline")

    @kb.predicate("sensor", 1)
    def sensor(value: object) -> Iterator[None]:
        raise boom
        yield None

    with pytest.raises(RuntimeError) as info:
        kb.holds("sensor(X)")  # nothing catches it: the caller gets its own exception
    assert info.value is boom
    assert any(frame.name == "sensor" for frame in info.traceback)
    # Inside the query it is a Prolog error that catch/3 can catch (issue 10).
    assert kb.holds("catch(sensor(X), error(python_error('RuntimeError', _), _), true)")


def test_py_fun_and_py_pred() -> None:
    kb = KnowledgeBase()
    kb.register_function("distance", lambda a, b: abs(a - b))
    assert kb.first("py_fun(distance, 3, 10, D)") == {"D": 7}
    assert kb.first("py_fun(F, [3, 1, 2], S)", F=sorted) == {"S": [1, 2, 3]}
    assert kb.holds("py_pred(F, 4)", F=lambda x: x % 2 == 0)
    assert not kb.holds("py_pred(F, 3)", F=lambda x: x % 2 == 0)
    with pytest.raises(PrologError, match="register_function"):
        kb.holds("py_fun(nope, 1, R)")


def test_unknown_predicate_names_similar_ones() -> None:
    kb = KnowledgeBase()
    kb.consult("arm_joints(pr2, left, []).")
    with pytest.raises(UnknownPredicateError) as info:
        kb.holds("arm_joint(pr2, left, J)")
    assert info.value.name == "arm_joint" and info.value.arity == 3
    assert "arm_joints/3" in str(info.value)
    with pytest.raises(UnknownPredicateError, match="arm_joints/3"):
        kb.holds("arm_joints(pr2, J)")
    assert kb.first("catch(foo, error(existence_error(procedure, P), _), true)") == {
        "P": Term("/", ("foo", 0))
    }


def test_syntax_error_names_line_column_and_text() -> None:
    kb = KnowledgeBase()
    with pytest.raises(PrologSyntaxError) as info:
        kb.consult("ok(1).\nbad(X :- q.\n")
    assert info.value.line == 2 and info.value.column >= 5 and ":- q." in info.value.text
    with pytest.raises(PrologSyntaxError):
        kb.query("member(X, [1,2)")


def test_query_is_lazy_and_abandoning_is_safe() -> None:
    kb = KnowledgeBase()
    calls: list[int] = []

    @kb.predicate("gen", 1)
    def gen(x: object) -> Iterator[tuple[int]]:
        for i in range(1000):
            calls.append(i)
            yield (i,)

    answers = kb.query("gen(X)")
    assert calls == []
    assert next(answers) == {"X": 0} and calls == [0]
    del answers
    assert kb.first("gen(X), X > 2") == {"X": 3}


def test_deep_recursion_runs_in_bounded_memory() -> None:
    kb = KnowledgeBase()
    kb.consult("count(0). count(N) :- N > 0, M is N-1, count(M).")
    tracemalloc.start()
    try:
        assert kb.holds("count(30000)")
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 1_000_000


def test_first_argument_indexing_is_not_a_scan() -> None:
    """A bound first argument tries the one clause with that key, not 100,000 (the time per
    lookup is a figure of benchmarks/logic_bench.py, not a test)."""
    kb = KnowledgeBase()
    kb.consult("\n".join(f"fact({i}, v{i})." for i in range(100_000)))
    assert kb.first("fact(99999, V)") == {"V": "v99999"}
    assert [kb.first("fact(K, V)", K=i) for i in (0, 50_000, 99_999)] == [
        {"V": "v0"},
        {"V": "v50000"},
        {"V": "v99999"},
    ]
    fact = kb._preds[("fact", 2)]
    assert [len(fact.candidates(i)) for i in (0, 50_000, 99_999, 100_000)] == [1, 1, 1, 0]


def test_concurrent_queries_from_threads() -> None:
    kb = KnowledgeBase()
    kb.consult("n(1). n(2). n(3). sum3(S) :- findall(X, n(X), L), sum_list(L, S).")
    results: list[int] = []

    def work() -> None:
        for _ in range(200):
            results.append(kb.first("sum3(S)")["S"])  # type: ignore[index]

    threads = [threading.Thread(target=work) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results == [6] * 800


def test_current_kb_context() -> None:
    with pytest.raises(PrologError, match="using_kb"):
        current_kb()
    kb = KnowledgeBase()
    with using_kb(kb):
        assert current_kb() is kb
    assert kb.predicates() == []
    kb.consult("a(1). b(X) :- a(X).")
    assert kb.predicates() == ["a/1", "b/1"]

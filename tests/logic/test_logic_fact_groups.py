"""Loading fact groups: facts without arguments, atomic loads, overridable library."""

from __future__ import annotations

import threading

import pytest

from robocram.logic import FactGroupError, KnowledgeBase, PrologError


def test_facts_without_arguments_load() -> None:
    kb = KnowledgeBase()
    kb.consult("go.\nready :- go.\nstop.")
    assert kb.holds("ready") and kb.holds("stop")
    kb.add_fact_group("g", ["idle."])
    assert kb.holds("idle")


def test_user_program_overrides_library_predicates() -> None:
    kb = KnowledgeBase()
    # A textbook quicksort's partition/4 and a select/3 of one's own.
    kb.consult(
        """
        partition(_, [], [], []).
        partition(P, [X|Xs], [X|L], G) :- X =< P, !, partition(P, Xs, L, G).
        partition(P, [X|Xs], L, [X|G]) :- partition(P, Xs, L, G).
        select(X, [X|_]).
        """
    )
    assert kb.first("partition(3, [5, 1, 4, 2], L, G)") == {"L": [1, 2], "G": [5, 4]}
    assert kb.first("select(X, [a, b])") == {"X": "a"}
    # The library's own select/3 users still work, on the library's select/3.
    assert kb.first("selectchk(b, [a, b, c], R)") == {"R": ["a", "c"]}
    assert "partition/4" in kb.predicates()
    other = KnowledgeBase()  # another KB keeps the library version
    other.consult("small(X) :- X < 3.")
    assert other.first("partition(small, [1, 3], I, E)") == {"I": [1], "E": [3]}
    assert other.first("select(b, [a, b], R)") == {"R": ["a"]}


def test_failed_directive_leaves_the_group_as_it_was() -> None:
    kb = KnowledgeBase()
    kb.consult("color(red).", group="colors")
    with pytest.raises(PrologError, match="directive failed"):
        kb.consult("color(blue).\n:- color(green).", group="colors")
    assert [a["C"] for a in kb.query("color(C)")] == ["red"]
    with pytest.raises(PrologError):
        kb.consult("color(blue).\n:- atom_length(X, _).", group="colors")
    assert [a["C"] for a in kb.query("color(C)")] == ["red"]


def test_refused_clause_leaves_the_group_as_it_was() -> None:
    kb = KnowledgeBase()
    kb.consult("owned(x).", group="a")
    kb.consult("mine(1).", group="b")
    with pytest.raises(FactGroupError):
        kb.consult("mine(2). owned(y).", group="b")
    assert [a["X"] for a in kb.query("mine(X)")] == [1]


def test_reconsult_is_atomic_for_concurrent_queries() -> None:
    kb = KnowledgeBase()
    size = 2000  # big enough that loading a group spans several thread switches
    groups = [
        "\n".join(f"item({k}, {i})." for i in range(size)) + f"\ncount({k}, {size})."
        for k in (1, 2)
    ]
    kb.consult(groups[0], group="items")
    wrong: list[object] = []
    done = threading.Event()

    def reader() -> None:
        while not done.is_set():
            answer = kb.first("findall(K-I, item(K, I), L), length(L, N), count(_, C)")
            assert answer is not None
            if answer["N"] != size or answer["C"] != size or len(set(answer["L"])) != size:
                wrong.append(answer)

    threads = [threading.Thread(target=reader) for _ in range(2)]
    for t in threads:
        t.start()
    for round_ in range(8):
        kb.consult(groups[round_ % 2], group="items")
    done.set()
    for t in threads:
        t.join()
    assert wrong == []

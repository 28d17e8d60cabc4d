"""Logic state per knowledge base: frozen shared built-ins, per-KB library, bounded caches."""

from __future__ import annotations

import pytest

from robocram.logic import KnowledgeBase, builtin_terms, python_predicates
from robocram.logic.goal_writer import _FACTORIES, FACTORY_CACHE_SIZE, make_factory
from robocram.logic.knowledge_base import QUERY_CACHE_SIZE
from robocram.logic.lru import LRUCache
from robocram.logic.predicate import FrozenPred
from robocram.logic.system import library_predicates, system_predicates


def test_system_predicates_are_shared_and_read_only() -> None:
    a, b = KnowledgeBase(), KnowledgeBase()
    assert a._preds[("atom_length", 2)] is b._preds[("atom_length", 2)]
    pred = a._preds[("atom_length", 2)]
    assert isinstance(pred, FrozenPred)
    with pytest.raises(AttributeError, match="atom_length/2 is a system predicate"):
        pred.warm = 5
    with pytest.raises(TypeError):
        system_predicates()[("foo", 1)] = pred  # type: ignore[index]


def test_system_table_is_exactly_the_listed_builtins() -> None:
    table = system_predicates()
    for b in builtin_terms.BUILTINS + python_predicates.BUILTINS:
        for arity in b.arities:
            assert table[(b.name, arity)].fn is b.fn
    assert ("append", 3) not in table  # library predicates are per knowledge base


def test_library_predicates_are_per_knowledge_base() -> None:
    a, b = KnowledgeBase(), KnowledgeBase()
    pa, pb = a._preds[("append", 3)], b._preds[("append", 3)]
    assert pa is not pb
    assert all(x is not y for x, y in zip(pa.clauses, pb.clauses, strict=True))
    for _ in range(5):
        assert a.first("append(X, [c], [a, b, c])") == {"X": ["a", "b"]}
    assert pa.warm > 0 and any(c.calls for c in pa.clauses)
    # Querying `a` compiled nothing for `b`.
    assert pb.warm == 0 and pb.proc is None
    assert all(c.calls == 0 and c.run is None for c in pb.clauses)
    assert b.first("append(X, [c], [a, b, c])") == {"X": ["a", "b"]}


def test_library_predicates_fresh_each_call() -> None:
    first, second = library_predicates(), library_predicates()
    assert first.keys() == second.keys()
    assert first[("member", 2)] is not second[("member", 2)]


def test_lru_cache_keeps_recent_entries_within_its_size() -> None:
    cache: LRUCache[int, str] = LRUCache(3)
    for i in range(3):
        cache.put(i, str(i))
    assert cache.get(0) == "0"  # 0 is now the most recent
    cache.put(3, "3")
    assert len(cache) == 3
    assert cache.get(1) is None  # the least recently used went first
    assert cache.keys() == [2, 0, 3]
    with pytest.raises(ValueError, match="at least 1"):
        LRUCache(0)


def test_query_cache_is_bounded() -> None:
    kb = KnowledgeBase()
    for i in range(QUERY_CACHE_SIZE + 50):
        assert kb.first(f"X = {i}") == {"X": i}
    assert len(kb._queries) == QUERY_CACHE_SIZE
    assert kb._queries.get(("string", "X = 0")) is None
    assert kb._queries.get(("string", f"X = {QUERY_CACHE_SIZE + 49}")) is not None


def test_generated_code_cache_is_bounded() -> None:
    for i in range(FACTORY_CACHE_SIZE + 10):
        make = make_factory(f"def make():\n  return {i}\n")
        assert make() == i
    assert len(_FACTORIES) == FACTORY_CACHE_SIZE
    assert _FACTORIES.get("def make():\n  return 0\n") is None  # the oldest went first


def test_every_listed_builtin_module_table_is_installed() -> None:
    kb = KnowledgeBase()
    assert kb.first("number_chars(X, ['1', '2'])") == {"X": 12}
    assert kb.first("number_codes(X, [0'7])") == {"X": 7}
    assert len(system_predicates()) > 120  # every table counted (control + ~60 built-ins)

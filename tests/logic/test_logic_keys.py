"""Predicate keys: the knowledge base's table and clause code share one key object."""

from __future__ import annotations

from robocram.logic import KnowledgeBase
from robocram.logic.keys import pred_key


def test_table_keys_are_the_shared_objects() -> None:
    # A call's key in clause code is pred_key(name, arity); the table holds that very
    # object, so the machine's look-up matches it by identity.
    kb = KnowledgeBase()
    kb.consult("p(1, a). p(2, b).\nq(X) :- p(X, _).\n")
    table = {k: k for k in kb._preds}
    for name, arity in [("p", 2), ("q", 1)]:
        assert table[(name, arity)] is pred_key(name, arity)
    assert [a["X"] for a in kb.query("q(X)")] == [1, 2]


def test_pred_key_is_equal_to_a_plain_key() -> None:
    key = pred_key("r", 3)
    assert key == ("r", 3) and hash(key) == hash(("r", 3))
    assert pred_key("r", 3) is key and pred_key("r", 2) is not key

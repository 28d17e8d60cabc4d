"""One shared tuple object per predicate key (name, arity), so dictionary look-ups match it
by identity.

The machine finds a called predicate by its key in the knowledge base's table at every
call. A key built anew is equal to the table's but another object, so each look-up
compares the two tuples item by item; clause code and the tables holding the same
object skip that comparison. The keys are kept in the one bounded store (lru.py): a key
dropped there only costs that comparison for the tables and code made before.
"""

from __future__ import annotations

from robocram.logic.lru import LRUCache

__all__ = ["pred_key"]

Key = tuple[str, int]
_KEYS: LRUCache[Key, Key] = LRUCache(1 << 16)


def pred_key(name: str, arity: int) -> Key:
    """The shared key object of name/arity.

    >>> pred_key("p", 2) is pred_key("p", 2)
    True
    """
    key = (name, arity)
    return _KEYS.get_or_build(key, lambda: key)

"""One shared tuple object per predicate key (name, arity), so dictionary look-ups match it
by identity.

The machine finds a called predicate by its key in the knowledge base's table at every
call. A key built anew is equal to the table's but another object, so each look-up
compares the two tuples item by item; clause code and the tables holding the same
object skip that comparison. The table is bounded: past its size it starts again, which
only costs that comparison for keys made before.
"""

from __future__ import annotations

__all__ = ["pred_key"]

_LIMIT = 1 << 16
_KEYS: dict[tuple[str, int], tuple[str, int]] = {}


def pred_key(name: str, arity: int) -> tuple[str, int]:
    """The shared key object of name/arity.

    >>> pred_key("p", 2) is pred_key("p", 2)
    True
    """
    key = (name, arity)
    found = _KEYS.get(key)
    if found is not None:
        return found
    if len(_KEYS) >= _LIMIT:
        _KEYS.clear()
    _KEYS[key] = key
    return key

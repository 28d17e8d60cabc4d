"""A bounded store: the one place where kept values are dropped when a bound is reached.

Caches keyed by program text grow with every distinct query or clause shape a long-lived
process sees; the bound keeps memory flat while the working set stays hot. The same store
keeps the kinematics' solvers and start tables and the hands read from descriptions (on
their models): values derived from immutable inputs, so an entry is never stale, only
dropped when the bound is reached. What depends on a world that changes is kept in a
``world.Derived``, which keeps its values here with the world's change counters they were
built at: one store, one rule of validity.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from collections.abc import Callable
from typing import Generic, TypeVar

from robocram.logic.usage_errors import LogicArgumentError

__all__ = ["LRUCache"]

K = TypeVar("K")
V = TypeVar("V")


class LRUCache(Generic[K, V]):
    """Keep at most `size` entries (None: no bound), dropping the least recently used first,
    or with ``recency=False`` the first stored (a read or a new value keeps a key's place).

    >>> c: LRUCache[str, int] = LRUCache(2)
    >>> c.put("a", 1); c.put("b", 2); _ = c.get("a"); c.put("c", 3)
    >>> sorted(c.keys())
    ['a', 'c']
    """

    def __init__(self, size: int | None, recency: bool = True) -> None:
        if size is not None and size < 1:
            raise LogicArgumentError(f"LRUCache size must be at least 1, got {size}")
        self.size = size
        self.recency = recency
        self._items: OrderedDict[K, V] = OrderedDict()
        self._lock = threading.Lock()  # queries on one KB may run in several threads

    def get(self, key: K) -> V | None:
        """The value for `key` (marking it recently used), or None."""
        with self._lock:
            items = self._items
            value = items.get(key)
            if value is not None and self.recency:
                items.move_to_end(key)
            return value

    def put(self, key: K, value: V) -> None:
        """Store `value`, evicting the least recently used entry when full."""
        with self._lock:
            items = self._items
            items[key] = value
            if self.recency:
                items.move_to_end(key)
            if self.size is not None and len(items) > self.size:
                items.popitem(last=False)

    def get_or_build(self, key: K, build: Callable[[], V]) -> V:
        """The value for ``key``, or ``build()`` (called outside the lock) kept for it."""
        found = self.get(key)
        if found is None:
            found = build()
            self.put(key, found)
        return found

    def clear(self) -> None:
        """Forget every entry."""
        with self._lock:
            self._items.clear()

    def keys(self) -> list[K]:
        """The keys, least recently used first."""
        return list(self._items)

    def __len__(self) -> int:
        return len(self._items)

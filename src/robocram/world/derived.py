"""Values derived from a world, each kept with the change counters it was built at.

A cache says once what its values depend on (``depends``: from the world's
:class:`~robocram.world.versions.Versions` and a key, the stamp to compare, e.g. a
body's pose and joints, or the structure); asked for a key, it answers the kept value
while that stamp is unchanged and builds it again otherwise. No caller compares states,
poses or handles by hand, so a value cannot outlive what it was read from. A bound
(``size``) drops the oldest key, or with ``lru`` the least recently asked. A store that
depends on counters serves one world (each world's clock starts at 0): keep it with
that world (:meth:`~robocram.world.World.derived`).

Values that depend on nothing but their key (an answer per posture, a table per set of
inputs) declare no ``depends`` and keep only the bound.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable
from typing import Generic, TypeVar

from robocram.logic.lru import LRUCache
from robocram.world.errors import WorldValueError
from robocram.world.versions import Versions

K = TypeVar("K", bound=Hashable)
V = TypeVar("V")


class Derived(Generic[K, V]):
    """Per key, a value and the stamp (``depends(versions, key)``) it was built at."""

    def __init__(
        self,
        depends: Callable[[Versions, K], Hashable] | None = None,
        size: int | None = None,
        lru: bool = False,
    ) -> None:
        if size is not None and size < 1:
            raise WorldValueError(f"a derived store keeps at least one value, got size={size}")
        self._depends = depends
        self._kept: LRUCache[K, tuple[Hashable, V]] = LRUCache(size, recency=lru)
        self.builds = 0  # values built so far (a test counts them)

    def get(self, key: K, build: Callable[[], V], versions: Versions | None = None) -> V:
        """The value of ``key``: the kept one if what it depends on (read from the world's
        ``versions``) is unchanged, else ``build()`` (kept in its place)."""
        stamp: Hashable = None
        if self._depends is not None:
            if versions is None:
                raise WorldValueError(
                    "this derived store depends on a world's counters: pass versions="
                    "world.versions to get()"
                )
            stamp = self._depends(versions, key)
        kept = self._kept.get(key)
        if kept is not None and kept[0] == stamp:
            return kept[1]
        value = build()
        self.builds += 1
        self._kept.put(key, (stamp, value))  # a stale key keeps its place (without lru)
        return value

    def __len__(self) -> int:
        return len(self._kept)

    def clear(self) -> None:
        """Drop every kept value."""
        self._kept.clear()

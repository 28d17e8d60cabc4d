"""Change counters of a world: what derived data compares instead of the state itself.

Every write to a world stamps what it changed with the next tick of one clock per world:
a body's pose (its base moved: placed, carried, restored, stepped), its joints (set,
restored, stepped) and the world's structure (bodies added or removed, attachments made
or dropped). A cache keeps the stamps its value was built at and builds again when one
differs (:class:`~robocram.world.derived.Derived`). Ticks never repeat, so a body removed
and added again under its name, or an object put back after a visit elsewhere, never
looks unchanged. Reading a stamp is a dictionary lookup; reads never change a stamp.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Protocol

from robocram.world.errors import UnknownObjectError
from robocram.world.world_object import WorldObject

Stamp = tuple[int, ...]  # counters compared as one value
Named = str | WorldObject  # a body by its name or its handle


class Versions:
    """Per body of a world, when it was created, last moved and last had its joints
    changed, and when the world's structure last changed, as ticks of one clock."""

    def __init__(self) -> None:
        self._tick = 0
        self._structure = 0
        self._created: dict[str, int] = {}
        self._pose: dict[str, int] = {}
        self._joints: dict[str, int] = {}

    @property
    def structure(self) -> int:
        """When bodies were last added or removed, or attachments changed."""
        return self._structure

    @property
    def tick(self) -> int:
        """The last tick handed out: it grows with every write the world sees."""
        return self._tick

    def created(self, name: Named) -> int:
        """When the body called ``name`` got its current physics body (its identity)."""
        return self._read(self._created, name)

    def pose(self, name: Named) -> int:
        """When the base of the body called ``name`` last moved."""
        return self._read(self._pose, name)

    def joints(self, name: Named) -> int:
        """When a joint of the body called ``name`` last changed."""
        return self._read(self._joints, name)

    def body(self, name: Named) -> Stamp:
        """Everything the shapes of the body called ``name`` depend on: its identity, its
        pose and its joints (one value to compare)."""
        return (self.created(name), self.pose(name), self.joints(name))

    def bodies(self, names: Iterable[Named]) -> Stamp:
        """:meth:`body` of each of ``names``, in their order, as one flat stamp (read in
        one loop: an obstacle table's stamp names every body of a kitchen, asked at every
        check; a body is in all three tables or in none)."""
        created, pose, joints = self._created, self._pose, self._joints
        flat: list[int] = []
        for name in names:
            key = name.name if isinstance(name, WorldObject) else name
            made = created.get(key)
            if made is None:
                raise UnknownObjectError(key, created)
            flat += (made, pose[key], joints[key])
        return tuple(flat)

    def _read(self, table: dict[str, int], name: Named) -> int:
        key = name.name if isinstance(name, WorldObject) else name
        found = table.get(key)
        if found is None:
            raise UnknownObjectError(key, self._created)
        return found

    # -- writes: only the world's own write paths call these --------------------------

    def added(self, name: str) -> None:
        """A body called ``name`` was created: everything about it is new."""
        tick = self._next()
        self._created[name] = self._pose[name] = self._joints[name] = tick
        self._structure = tick

    def removed(self, name: str) -> None:
        """The body called ``name`` left the world."""
        for table in (self._created, self._pose, self._joints):
            table.pop(name, None)
        self._structure = self._next()

    def restructured(self) -> None:
        """Attachments changed: what moves with what is different."""
        self._structure = self._next()

    def moved(self, name: str) -> None:
        """The base of the body called ``name`` was moved."""
        self._pose[name] = self._next()

    def jointed(self, name: str) -> None:
        """A joint of the body called ``name`` was changed."""
        self._joints[name] = self._next()

    def stepped(self, names: Iterable[str], jointed: Iterable[str]) -> None:
        """Physics ran: ``names`` may have moved, ``jointed`` may have changed joints."""
        tick = self._next()
        for name in names:
            self._pose[name] = tick
        for name in jointed:
            self._joints[name] = tick

    def _next(self) -> int:
        self._tick += 1
        return self._tick


@dataclass(frozen=True)
class BodyStamps:
    """Some bodies' counters and states at one time, to ask later which of them changed:
    what a planned motion was checked against (:func:`changed_bodies`)."""

    tick: int  # the world's clock then: unchanged, nothing at all changed
    stamps: tuple[tuple[str, Stamp], ...]
    states: tuple[tuple[float, ...], ...]  # per body, its state then (body_state)


class _StateReader(Protocol):
    """The part of a world that reads a body's state (``world.snapshots``)."""

    def body_state(self, obj: str) -> tuple[float, ...]: ...


class _StampedWorld(Protocol):
    """What :class:`BodyStamps` reads of a world."""

    @property
    def versions(self) -> Versions: ...

    @property
    def snapshots(self) -> _StateReader: ...


MOVED = 1e-6  # [m | rad] a body's state changed by less (Bullet's round trips, creep): still


def body_stamps(world: _StampedWorld, names: Iterable[str]) -> BodyStamps:
    """The counters and states of the bodies called ``names`` now."""
    names = list(names)
    versions = world.versions
    return BodyStamps(
        versions.tick,
        tuple((n, versions.body(n)) for n in names),
        tuple(world.snapshots.body_state(n) for n in names),
    )


def changed_bodies(world: _StampedWorld, then: BodyStamps, names: Iterable[str]) -> list[str]:
    """Which of the bodies called ``names`` are new since ``then``, or were written since
    and stand otherwise (by more than :data:`MOVED`; the counters say where to look)."""
    versions = world.versions
    if versions.tick == then.tick:
        return []
    kept = {n: (s, state) for (n, s), state in zip(then.stamps, then.states, strict=True)}
    found = []
    for name in names:
        old = kept.get(name)
        if old is not None and old[0] == versions.body(name):
            continue
        if old is not None and _same_state(old[1], world.snapshots.body_state(name)):
            continue
        found.append(name)
    return found


def _same_state(old: tuple[float, ...], now: tuple[float, ...]) -> bool:
    return len(old) == len(now) and all(abs(a - b) <= MOVED for a, b in zip(old, now, strict=True))

"""Which objects a location's refused candidates failed on, so a failure can name them.

Validators and lazy layers record, only for a candidate they refuse, the objects that made
them refuse it: what the rays met before the target (``occluding``) and what the robot
would touch standing or reaching there (``blocking``). A candidate counts each object once.
When no candidate passes, :class:`~robocram.costmaps.errors.LocationNotFound` names the
most frequent (:meth:`LocationBlame.culprits`): an object that hides the target from, or
blocks, nearly every candidate is the one to move.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field

CULPRIT_SHARE = 0.5  # an object is named if it failed at least this share of the candidates
# the most frequent one failed: the leading blocker and any about as frequent, not strays


@dataclass(frozen=True)
class Culprits:
    """The objects to name: what hid the target, what blocked the stands, and how often.

    ``occluders`` and ``blockers`` count, per object blamed (innocent ones left out), the
    refused candidates it was blamed for; ``occluded`` and ``blocked`` how many refused
    candidates blamed any object at all.
    """

    target: str
    occluded_by: tuple[str, ...] = ()
    blocked_by: tuple[str, ...] = ()
    occluders: Mapping[str, int] = field(default_factory=dict)
    blockers: Mapping[str, int] = field(default_factory=dict)
    occluded: int = 0
    blocked: int = 0

    def __bool__(self) -> bool:
        return bool(self.occluded_by or self.blocked_by)


@dataclass
class LocationBlame:
    """Per kind, how many refused candidates blamed each object (one resolution's tally)."""

    occluders: Counter[str] = field(default_factory=Counter)
    blockers: Counter[str] = field(default_factory=Counter)
    occluded: int = 0  # refused candidates that blamed an occluder
    blocked: int = 0  # refused candidates that blamed a blocker
    pending: list[Callable[[LocationBlame], None]] = field(default_factory=list)
    # tallies a layer leaves for a failure to run (what ruled cells out, worked out only then)

    def later(self, tally: Callable[[LocationBlame], None]) -> None:
        """Run ``tally`` on this blame only if the location fails (:meth:`culprits`)."""
        self.pending.append(tally)

    def occluding(self, names: Iterable[str]) -> None:
        """One refused candidate from which ``names`` hid the target."""
        found = set(names)
        if found:
            self.occluders.update(found)
            self.occluded += 1

    def blocking(self, names: Iterable[str]) -> None:
        """One refused candidate where the robot would touch ``names``."""
        found = set(names)
        if found:
            self.blockers.update(found)
            self.blocked += 1

    def blocking_cells(self, counts: Mapping[str, int], cells: int) -> None:
        """``cells`` refused cells at once, ``counts[name]`` of them blocked by ``name``."""
        if cells:
            self.blockers.update(counts)
            self.blocked += cells

    def culprits(
        self, target: str, innocent: Iterable[str] = (), fixed: Iterable[str] = ()
    ) -> Culprits:
        """The objects to name for ``target``: neither ``innocent`` ones (the robot, the
        target, what it holds) nor ``fixed`` ones (an environment's walls and counters,
        which hide things from far-off cells and stand in the way of some stands in any
        scene): moving them is no remedy. Fixed ones still show in the counts. The tallies
        left for later are run first."""
        while self.pending:
            self.pending.pop(0)(self)
        spared, walls = set(innocent), set(fixed)
        occluders = {k: n for k, n in self.occluders.items() if k not in spared}
        blockers = {k: n for k, n in self.blockers.items() if k not in spared}
        return Culprits(
            target,
            _leaders(occluders, walls),
            _leaders(blockers, walls),
            occluders,
            blockers,
            self.occluded,
            self.blocked,
        )


def _leaders(tally: Mapping[str, int], fixed: set[str]) -> tuple[str, ...]:
    """The movable names counted at least :data:`CULPRIT_SHARE` of the top one's count,
    most first."""
    ranked = sorted(
        ((name, n) for name, n in tally.items() if name not in fixed),
        key=lambda item: (-item[1], item[0]),
    )
    if not ranked:
        return ()
    least = CULPRIT_SHARE * ranked[0][1]
    return tuple(name for name, n in ranked if n >= least)


def culprit_sentence(culprits: Culprits) -> str:
    """What hides or blocks the target, how often, and what to do; empty if nothing named.

    >>> text = culprit_sentence(
    ...     Culprits("mug-1", ("box-3",), occluders={"box-3": 8, "wall": 2}, occluded=9)
    ... )
    >>> for part in text.split("; "):
    ...     print(part)
    mug-1 is hidden from every stand by box-3 (in the way at 8 of the 9 candidates refused
    also in the way: wall 2)
    move box-3 or look from elsewhere
    """
    parts = []
    target = culprits.target
    if culprits.occluded_by:
        names, counts = culprits.occluded_by, culprits.occluders
        tally = _tally(names, counts, culprits.occluded, "also in the way")
        parts.append(
            f"{target} is hidden from every stand by {_listed(names)} (in the way at {tally}); "
            f"move {_listed(names)} or look from elsewhere"
        )
    if culprits.blocked_by:
        names, counts = culprits.blocked_by, culprits.blockers
        tally = _tally(names, counts, culprits.blocked, "also in the way")
        parts.append(
            f"every stand for {target} is blocked by {_listed(names)} (in the way at {tally}); "
            f"move {_listed(names)} or stand elsewhere"
        )
    return "; ".join(parts)


def _listed(names: tuple[str, ...]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def _tally(named: tuple[str, ...], counts: Mapping[str, int], total: int, also: str) -> str:
    """``8 of the 9 candidates refused; also in the way: wall 2`` (one count per name)."""
    shown = _listed(tuple(str(counts[name]) for name in named))
    rest = sorted(((n, name) for name, n in counts.items() if name not in named), reverse=True)
    tail = f"; {also}: " + ", ".join(f"{name} {n}" for n, name in rest) if rest else ""
    return f"{shown} of the {total} candidates refused{tail}"

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
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Literal

BlameKind = Literal["occluded", "blocked"]
CULPRIT_SHARE = 0.5  # an object is named if it failed at least this share of the candidates
# the most frequent one failed: the leading blocker and any about as frequent, not strays


@dataclass(frozen=True)
class Culprits:
    """The objects to name: what hid the target, what blocked the stands, and how often.

    ``counts`` holds, per named object, how many refused candidates it was blamed for;
    ``occluded`` and ``blocked`` how many refused candidates blamed any object at all.
    """

    target: str
    occluded_by: tuple[str, ...] = ()
    blocked_by: tuple[str, ...] = ()
    counts: Mapping[str, int] = field(default_factory=dict)
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

    def culprits(self, target: str, innocent: Iterable[str] = ()) -> Culprits:
        """The objects to name for ``target``, ``innocent`` ones (the robot, the target, what
        it holds: moving them is no remedy) left out."""
        spared = set(innocent)
        occluded_by = _leaders(self.occluders, spared)
        blocked_by = _leaders(self.blockers, spared)
        counts = {name: self.occluders[name] for name in occluded_by}
        counts.update({name: self.blockers[name] for name in blocked_by})
        return Culprits(target, occluded_by, blocked_by, counts, self.occluded, self.blocked)


def _leaders(tally: Counter[str], spared: set[str]) -> tuple[str, ...]:
    """The names counted at least :data:`CULPRIT_SHARE` of the top count, most first."""
    ranked = sorted(
        ((n, name) for name, n in tally.items() if name not in spared), key=lambda x: (-x[0], x[1])
    )
    if not ranked:
        return ()
    least = CULPRIT_SHARE * ranked[0][0]
    return tuple(name for n, name in ranked if n >= least)


def culprit_sentence(culprits: Culprits) -> str:
    """What hides or blocks the target, how often, and what to do; empty if nothing named."""
    parts = []
    if culprits.occluded_by:
        parts.append(
            f"{culprits.target} is hidden from every stand by {_listed(culprits.occluded_by)} "
            f"({_tally(culprits, culprits.occluded_by, culprits.occluded, 'occluded')}); "
            f"move {_listed(culprits.occluded_by)} or look from elsewhere"
        )
    if culprits.blocked_by:
        parts.append(
            f"every stand for {culprits.target} is blocked by {_listed(culprits.blocked_by)} "
            f"({_tally(culprits, culprits.blocked_by, culprits.blocked, 'blocked')}); "
            f"move {_listed(culprits.blocked_by)} or stand elsewhere"
        )
    return "; ".join(parts)


def _listed(names: tuple[str, ...]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def _tally(culprits: Culprits, names: tuple[str, ...], total: int, kind: BlameKind) -> str:
    verb = "in the way" if kind == "occluded" else "touched"
    return ", ".join(
        f"{name} {verb} at {culprits.counts[name]} of {total} refused" for name in names
    )

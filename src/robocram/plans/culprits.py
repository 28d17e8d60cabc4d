"""The objects a plan's failed tries blamed, carried up into the failure that ends it.

A location that found no stand (``LocationNotFound``) names what hid the target
(``occluded_by``) and what blocked the stands (``blocked_by``); perception that saw the
object's place but not the object names what hid it (``PerceptionObjectNotFound``'s
``occluded_by``). The plans read those fields by name (costmaps lie above this layer),
rank the objects by how many causes named them, and say them where a user reads first.

>>> class Hidden(Exception):
...     occluded_by = ("box-3",)
>>> blamed([Hidden(), ValueError(), Hidden()], "occluded_by")
('box-3',)
>>> culprit_clause((), ("box-1", "box-2"))
', blocked by box-1 and box-2 (move them or stand elsewhere)'
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable


def blamed(causes: Iterable[BaseException], field: str) -> tuple[str, ...]:
    """The objects the causes' ``field`` (``occluded_by`` or ``blocked_by``) names, most
    often named first, then in the order first named."""
    tally: Counter[str] = Counter()
    for cause in causes:
        tally.update(list(dict.fromkeys(getattr(cause, field, None) or ())))
    return tuple(name for name, _ in tally.most_common())


def _listed(names: tuple[str, ...]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def culprit_clause(occluded_by: tuple[str, ...], blocked_by: tuple[str, ...]) -> str:
    """``, hidden by box-3 (move it or look from elsewhere)``; empty when none is named."""
    parts = []
    for names, what, elsewhere in (
        (occluded_by, "hidden", "look from elsewhere"),
        (blocked_by, "blocked", "stand elsewhere"),
    ):
        if names:
            it = "it" if len(names) == 1 else "them"
            parts.append(f", {what} by {_listed(names)} (move {it} or {elsewhere})")
    return "".join(parts)

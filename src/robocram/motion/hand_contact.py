"""The contact CRAM's ``allow_hand`` allows: the hand on what it acts on, and not deep.

A hand closing round a mug, or round a drawer's handle, must touch it. Letting the hand's
links touch anything at any depth let a joint-space fallback sweep the fingers through a
counter (issue 35). A :class:`HandContact` names what the hand acts on (an object, or
``object/link`` for a handle; :data:`ANY_OBJECT` when the caller names none) and bounds
how deep the hand may go into it (:data:`HAND_CONTACT_DEPTH`). Every other contact of
the hand is a collision. A trajectory stores it as :class:`ContactAllowance` s, so the
audit (``robocram runs audit``) holds the motion to the same bound.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass, replace

from robocram.motion.contact_allowance import ContactAllowance
from robocram.world import World
from robocram.world.world_tables import ObjectRef

HAND_CONTACT_DEPTH = 0.005  # [m] the deepest the hand may go into what it acts on
KEEP_DEPTH = 0.0005  # [m] a contact a motion starts with may deepen by this (numerics)
ANY_OBJECT = "*"  # a hand contact naming no object: any object, within the same bound


@dataclass(frozen=True)
class HandContact:
    """``links`` may touch ``touchable`` (names or ``object/link``), at most ``depth`` deep."""

    links: frozenset[str]
    touchable: frozenset[str]
    depth: float = HAND_CONTACT_DEPTH

    @classmethod
    def of(cls, links: Collection[str], touching: str | None) -> HandContact:
        """The hand ``links`` on ``touching`` (None: any object, within the bound)."""
        return cls(frozenset(links), frozenset({touching or ANY_OBJECT}))

    def covers(self, link: str, named: str) -> bool:
        """Whether robot ``link`` touching ``named`` (an object or ``object/link``) is
        this contact (then only its depth can make it a collision)."""
        if link not in self.links:
            return False
        touchable = self.touchable
        return ANY_OBJECT in touchable or named in touchable or named.split("/")[0] in touchable

    def allowances(self) -> tuple[ContactAllowance, ...]:
        """The contact as a trajectory stores it: per hand link and thing touched."""
        return tuple(
            ContactAllowance(link, other, self.depth)
            for link in sorted(self.links)
            for other in sorted(self.touchable)
        )


def contact_depth(world: World, robot: ObjectRef, link: str, named: str) -> float:
    """How deep [m] robot ``link`` is in ``named`` (an object or ``object/link``) as they
    stand: 0 when they only touch or are apart."""
    name, _, other_link = named.partition("/")
    points = world.contacts.contact_points(robot, name, link, other_link or None, 0.0)
    return max((-p.distance for p in points), default=0.0)


def hand_at_start(world: World, robot: ObjectRef, hand: HandContact | None) -> HandContact | None:
    """``hand`` bounded for a motion starting where ``robot`` stands: its bound, or, where
    its links are already deeper in what they act on (a drawer's step pulled the hand into
    the handle), that depth and :data:`KEEP_DEPTH` more. A contact the motion starts with
    is kept, never deepened: a hand backing off a mug it had let go swept a finger 29 mm
    into it while its start contact was allowed at any depth (issue 35)."""
    if hand is None:
        return None
    deepest = 0.0
    body = world.object(robot)
    links = [link for link in hand.links if link in body.link_index]
    held = world.bodies.attachments(body)  # they move with it: their bounds change
    boxes = None if held else world.contacts.obstacle_boxes([body])  # one comparison
    for link, other, other_link, gap in world.contacts.link_distances(
        robot, distance=0.0, links=links, obstacles=boxes
    ):
        named = f"{other.name}/{other_link}" if len(other.link_index) > 1 else other.name
        if gap < 0.0 and hand.covers(link, named):
            deepest = max(deepest, -gap)
    if deepest + KEEP_DEPTH <= hand.depth:
        return hand
    return replace(hand, depth=deepest + KEEP_DEPTH)

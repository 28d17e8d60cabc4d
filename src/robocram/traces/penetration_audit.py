"""Penetrations of a robot (and what it holds) with the world and with itself, raw.

PyBullet answers for every pair of links, through :class:`robocram.world.RawDistances`
only: its own link bounds pick the pairs that may touch (bounds that do not overlap
cannot hide a penetration), and its closest points give the depth. Nothing of the
planner's checker is used. Per configuration, only the parts that moved since the last
one are asked about again.

Who may touch what:
- robot links and objects of type ``floor``: any depth (the base stands on it);
- a hand (an arm's hand and gripper links, and the link holding it) and the object its
  arm holds: ``held_depth``;
- what the trajectory's :class:`~robocram.motion.ContactAllowance` s allow: their depth;
- anything else, the robot's own non-adjacent links included: ``penetration``.
A contact allowed but deeper than its bound is its own kind of finding.
"""

from __future__ import annotations

import itertools
from collections.abc import Collection, Iterable, Iterator, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from robocram.motion import ContactAllowance
from robocram.robots import LoadedDescription
from robocram.traces.audit_bounds import AuditBounds
from robocram.traces.audit_findings import FindingKind
from robocram.traces.link_adjacency import LinkPair
from robocram.world import Attachment, LinkSlot, RawDistances, RobotHandle

FloatArray = NDArray[np.float64]
# [m] how far apart pairs are asked for: asked for exactly 0, Bullet sometimes reports no
# points for two penetrating links of one body, so the question reaches a hair farther
QUERY_REACH = 1e-4
# [m] how far round the moving parts' bounds the others near them are gathered: a smaller
# box the parts stay within needs no new gathering (the pairs asked about are the same)
NEAR_MARGIN = 0.05
_SIGN = np.array([1.0, 1.0, 1.0, -1.0, -1.0, -1.0])  # (low, high) -> (low, -high): exact
_HALVES = np.array([3, 4, 5, 0, 1, 2])  # (a, b) -> (b, a)
_ALL_BELOW = np.uint64(0x0101010101010101)  # 8 booleans, all True, read as one word


def _signed(boxes: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Bounds (k, 2, 3) as ``(low, -high)`` and ``(high, -low)`` rows (k, 6): boxes A and
    B overlap exactly when every entry of A's first is <= B's second (``low_A <= high_B``
    and ``low_B <= high_A``), one comparison instead of two (negation is exact)."""
    low = boxes.reshape(len(boxes), 6) * _SIGN
    return low, -low[:, _HALVES]


@dataclass(frozen=True)
class Part:
    """One link with collision shapes: of the robot, of a held object, or of the world."""

    body: str
    link: str
    only: bool = False  # the body's only link with collision shapes

    @property
    def label(self) -> str:
        """``body:link``, or the body's name alone when it has one link with shapes."""
        return self.body if self.only else f"{self.body}:{self.link}"


@dataclass(frozen=True)
class Penetration:
    """A pair deeper than it may be, at one configuration."""

    kind: FindingKind
    what: str
    depth: float  # [m]
    bound: float  # [m]


class PenetrationProbe:
    """The pairs of one robot, in one world, during one trajectory (nothing else moves)."""

    def __init__(
        self,
        robot: RobotHandle,
        held: dict[str, str],  # held object -> the robot link it is attached to
        allowances: Sequence[ContactAllowance],
        bounds: AuditBounds,
        skipped: Collection[LinkPair],
        groups: Sequence[str] | None = None,
    ) -> None:
        """``skipped``: pairs of the robot's links not judged (adjacent, always touching);
        ``groups``: per part of :func:`robot_side_parts`, its moving group
        (:func:`~robocram.traces.relative_motion.moving_groups`; ``""`` does not move);
        None: every part moves and every pair is judged."""
        world = robot.world
        self.raw = RawDistances(world)
        self.bounds = bounds
        self.allowances = tuple(allowances)
        self.robot = robot.name
        self.parts = robot_side_parts(robot, held)
        labels = np.array(groups if groups is not None else range(len(self.parts)), dtype=object)
        self._moving = np.flatnonzero(labels != "") if groups is not None else None
        self._all_rows = np.arange(len(self.parts))
        self._moving_slots: list[LinkSlot] = []
        floors = {o.name for o in world.objects(type="floor")}
        others = [o.name for o in world.objects() if o.name != robot.name and o.name not in held]
        self.others = [part for o in others for part in _parts_of(self.raw, o)]
        self._slots = self._slots_of(self.parts)
        if self._moving is not None:
            self._moving_slots = [self._slots[i] for i in self._moving]
        self._other_slots = self._slots_of(self.others)
        self._other_boxes = self.raw.slot_bounds(self._other_slots)
        self._other_high = _signed(self._other_boxes)[1]  # (high, -low) of each other
        self._moved_rows: dict[tuple[tuple[str, str], ...], NDArray[np.intp]] = {}
        # what hangs from what: nothing is attached or let go during one trajectory
        self._attachments = tuple(world.bodies.all_attachments())
        self._near: NDArray[np.intp] | None = None  # others whose bounds meet _near_box
        self._near_box = np.zeros(6)  # (low, -high) of the box the near others meet
        self._near_high = np.zeros((0, 6))  # _other_high of the near others
        self._near_mask = np.zeros((0, 0), dtype=bool)  # _world_mask of the near others
        self._near_mask_moving = self._near_mask  # its rows of the moving parts
        self._hand_of = _hands(robot.description, held)
        mine = np.array([p.body == robot.name for p in self.parts], dtype=bool)
        floor = np.array([o.body in floors for o in self.others], dtype=bool)
        self._world_mask = ~(mine[:, None] & floor[None, :])  # robot links on floors: any depth
        pairs = self._judged_pairs(skipped)
        self._self_pairs = pairs[labels[pairs[:, 0]] != labels[pairs[:, 1]]]
        self._self_a, self._self_b = self._self_pairs[:, 0].copy(), self._self_pairs[:, 1].copy()
        # each part's bounds now, as _signed rows
        # (each padded with two zeros: 8 comparisons of a pair read as one 8-byte word)
        low, high = _signed(self.raw.slot_bounds(self._slots))
        self._low_now, self._high_now = np.zeros((len(low), 8)), np.zeros((len(low), 8))
        self._low_now[:, :6], self._high_now[:, :6] = low, high

    def _judged_pairs(self, skipped: Collection[LinkPair]) -> NDArray[np.intp]:
        """Pairs of parts (robot links, held objects) judged against each other."""
        pairs = []
        for i, a in enumerate(self.parts):
            for j in range(i + 1, len(self.parts)):
                b = self.parts[j]
                if a.body == b.body == self.robot and frozenset((a.link, b.link)) in skipped:
                    continue
                if a.body == b.body and a.body != self.robot:
                    continue  # one held object's own links
                pairs.append((i, j))
        return np.array(pairs, dtype=np.intp).reshape(-1, 2)

    def _slots_of(self, parts: Sequence[Part]) -> list[LinkSlot]:
        """Each part's PyBullet address, looked up once for the probe's life."""
        slots: list[LinkSlot] = []
        for body, links in itertools.groupby(parts, key=lambda p: p.body):
            slots += self.raw.slots(body, [p.link for p in links])
        return slots

    def others_moved(self, joints: Collection[tuple[str, str]]) -> None:
        """Read again the bounds of the parts that ``joints`` (object, joint) move: they
        moved with the robot (a drawer its hand pulls, :class:`~robocram.motion.CarriedJoint`),
        and so did the bodies riding on them (spoons in the drawer, attached to it); the
        object's other links stay where they were."""
        key = tuple(sorted(joints))
        rows = self._moved_rows.get(key)
        if rows is None:
            moved = {(o, link) for o, j in key for link in self.raw.links_moved_by(o, j)}
            moved |= {(o, link) for o, j in key for link in _child_link(self.raw, o, j)}
            riders = _riders(self._attachments, moved)
            rows = np.array(
                [
                    i
                    for i, p in enumerate(self.others)
                    if (p.body, p.link) in moved or p.body in riders
                ],
                dtype=np.intp,
            )
            self._moved_rows[key] = rows
        if len(rows):
            self._other_boxes[rows] = self.raw.slot_bounds([self._other_slots[i] for i in rows])
            self._other_high[rows] = _signed(self._other_boxes[rows])[1]
            self._near = None  # gathered from bounds that moved

    def check(self, first: bool) -> Iterator[Penetration]:
        """Penetrations now: at the ``first`` configuration of all parts, later only of
        the parts that move and the pairs that move relative to each other."""
        rows = self._moving if self._moving is not None and not first else self._all_rows
        moving = rows is self._moving
        low = self._low_now[:0, :6]
        if len(rows):
            low, high = _signed(self.raw.slot_bounds(self._moving_slots if moving else self._slots))
            self._low_now[rows, :6], self._high_now[rows, :6] = low, high
        yield from self._world(rows, low, moving)
        yield from self._self()

    def _world(
        self, rows: NDArray[np.intp], low: FloatArray, moving: bool
    ) -> Iterator[Penetration]:
        """``low``: the (low, -high) rows of the parts ``rows`` (the moving ones if
        ``moving``)."""
        if not len(rows) or not self.others:
            return
        near = self._near_others(low)
        if not len(near):
            return
        mask = self._near_mask_moving if moving else self._near_mask  # rows: all parts
        overlap = _all(low[:, None, :] <= self._near_high[None, :, :], 2) & mask
        for r, k in zip(*np.nonzero(overlap), strict=True):
            i, o = int(rows[r]), int(near[k])
            found = self._judged(
                self.parts[i], self.others[o], self._slots[i], self._other_slots[o]
            )
            if found is not None:
                yield found

    def _near_others(self, low: FloatArray) -> NDArray[np.intp]:
        """The others (ascending) whose bounds meet a box holding the moving parts' bounds
        (``low``: their (low, -high) rows): any other whose bounds meet a part's is among
        them."""
        least = np.minimum.reduce(low, axis=0)  # (least low, -greatest high)
        if self._near is None or np.logical_or.reduce(least < self._near_box):
            box_low, box_high = least[:3] - NEAR_MARGIN, -least[3:] + NEAR_MARGIN
            self._near_box = np.concatenate((box_low, -box_high))
            meets = (self._other_boxes[:, 0] <= box_high) & (box_low <= self._other_boxes[:, 1])
            self._near = np.flatnonzero(meets.all(axis=1))
            self._near_high = self._other_high[self._near]
            self._near_mask = self._world_mask[:, self._near]
            if self._moving is not None:
                self._near_mask_moving = self._near_mask[self._moving]
        return self._near

    def _self(self) -> Iterator[Penetration]:
        """The pairs moving relative to each other (all of them when no groups are given)."""
        pairs = self._self_pairs
        if not len(pairs):
            return
        below = self._low_now[self._self_a] <= self._high_now[self._self_b]  # (pairs, 8)
        overlap = below.view(np.uint64)[:, 0] == _ALL_BELOW  # every byte True (1)
        for i, j in pairs[overlap]:
            found = self._judged(self.parts[i], self.parts[j], self._slots[i], self._slots[j])
            if found is not None:
                yield found

    def _judged(
        self, mine: Part, other: Part, mine_at: LinkSlot, other_at: LinkSlot
    ) -> Penetration | None:
        """The pair's penetration if deeper than it may be (``*_at``: their slots)."""
        gap = self.raw.slot_distance(mine_at, other_at, QUERY_REACH)
        if gap is None or -gap <= self.bounds.penetration:
            return None  # within the general bound: never a finding, allowed or not
        depth = -gap
        bound = self._allowed_depth(mine, other)
        if bound is not None:
            if depth <= bound:
                return None
            kind = FindingKind.ALLOWED_CONTACT_TOO_DEEP
        else:
            own = mine.body == other.body == self.robot
            kind = FindingKind.SELF_PENETRATION if own else FindingKind.WORLD_PENETRATION
            bound = self.bounds.penetration
        return Penetration(kind, f"{mine.label} / {other.label}", depth, bound)

    def _allowed_depth(self, mine: Part, other: Part) -> float | None:
        """The deepest contact allowed between the two (None: none allowed)."""
        found = [
            a.depth
            for x, y in ((mine, other), (other, mine))
            for a in self.allowances
            if a.covers(_side(x, self.robot), y.body, y.link)
        ]
        for x, y in ((mine, other), (other, mine)):
            if (
                x.body != self.robot
                and y.body == self.robot
                and y.link in self._hand_of.get(x.body, ())
            ):
                found.append(self.bounds.held_depth)
        return max(found) if found else None


def _all(values: NDArray[np.bool_], axis: int) -> NDArray[np.bool_]:
    """``values.all(axis)`` without the method's Python wrapper (called per configuration)."""
    return np.logical_and.reduce(values, axis=axis)


def robot_side_parts(robot: RobotHandle, held: Iterable[str]) -> list[Part]:
    """The robot's links with collision shapes, then those of each held object."""
    world = robot.world
    raw = RawDistances(world)
    parts = [Part(robot.name, link) for link in raw.collision_links(robot.name)]
    return parts + [part for obj in held for part in _parts_of(raw, obj)]


def _parts_of(raw: RawDistances, body: str) -> list[Part]:
    links = raw.collision_links(body)
    return [Part(body, link, only=len(links) == 1) for link in links]


def _child_link(raw: RawDistances, obj: str, joint: str) -> list[str]:
    """The link ``joint`` of ``obj`` moves directly (none if no such joint): what rides on
    a drawer is attached to it, shapes or not (``trajectory_audit.riding``)."""
    handle = raw.world.object(obj)
    index = handle.joint_index.get(joint)
    return [name for name, i in handle.link_index.items() if index is not None and i == index]


def _riders(attachments: Collection[Attachment], moved: Collection[tuple[str, str]]) -> set[str]:
    """The bodies hanging from a ``moved`` (body, link), or from a body that does."""
    riders: set[str] = set()
    grew = True
    while grew:
        grew = False
        for a in attachments:
            if a.obj not in riders and (a.robot in riders or (a.robot, a.link) in moved):
                riders.add(a.obj)
                grew = True
    return riders


def _side(part: Part, robot_name: str) -> str:
    """The robot side's name in an allowance: a robot link, or a held object's name."""
    return part.link if part.body == robot_name else part.body


def _hands(description: LoadedDescription, held: dict[str, str]) -> dict[str, frozenset[str]]:
    """Per held object: the links of the hand holding it (hand, gripper, the holding link)."""
    hands: dict[str, frozenset[str]] = {}
    for obj, link in held.items():
        links = {link}
        for arm in description.arms.values():
            hand = {*arm.hand_links, *arm.gripper_links, arm.tool_frame, arm.end_effector_link}
            if link in hand or link in arm.links:
                links |= set(arm.hand_links) | set(arm.gripper_links)
        hands[obj] = frozenset(links)
    return hands

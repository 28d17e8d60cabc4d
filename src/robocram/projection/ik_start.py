"""Where the robot stands when an IK query starts: read once for every candidate it checks.

A candidate moves the links below its joints (the arm's, the torso's); the others stay
where they start, so what they touch is the same at every candidate of the query and is
asked once, as are their bounds; an object resting on one of them (a mug on a robot's own
table top) does not count. Self pairs touching at the start stay allowed; the start is
asked about a pair only when it touches at a candidate. What each candidate puts back is
read once too. A check asks :meth:`IKStart.holds` before each candidate and reads the
start again if anything but its own put-backs wrote to the robot since (the world's change
counters say; no state is compared); nothing but the robot may move in between.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from robocram.motion.hand_contact import HandContact, contact_depth
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import RobotModel
from robocram.world import WorldObject
from robocram.world.link_contacts import Bounds, link_bounds, link_pairs_in_contact, self_contacts
from robocram.world.versions import Stamp

LinkPair = tuple[str, str]  # (robot link, object or object/link | robot link)
RESTING = 0.9  # z of every contact normal out of a still link that an object rests on


@dataclass
class IKStart:
    """The robot's start for one query's checks; :meth:`colliding` tries a candidate."""

    robot: ProjectedRobot
    distance: float  # [m] closer than this is a collision
    stamp: Stamp  # the robot's change counters when it last stood as at the start
    joints: dict[str, float]  # the values to put back (mimic followers come with masters)
    unheld: frozenset[str]  # joints simulation does not hold where they are
    ignore: list[WorldObject]  # what may touch: the floor, what the robot holds
    alone: bool  # only the robot and what it holds (ignored) move: nothing they carry
    pairs: list[LinkPair]  # self pairs to check, unless they touch at the start
    _at_start: dict[LinkPair, bool] = field(default_factory=dict)  # pair -> touching
    _dirty: dict[str, float] = field(default_factory=dict)  # deferred: values to put back
    _touching: set[LinkPair] = field(default_factory=set)  # the pairs touching at the start
    _kept: dict[str, list[LinkPair]] = field(default_factory=dict)  # links that stay put
    _bounds: dict[int, Bounds] = field(default_factory=dict)  # of the links that stay put
    _moves: dict[tuple[str, ...], tuple[frozenset[int], list[LinkPair]]] = field(
        default_factory=dict
    )

    @classmethod
    def read(
        cls,
        robot: ProjectedRobot,
        distance: float,
        pairs: list[LinkPair],
        apart: bool = False,
    ) -> IKStart:
        """The start as it is now; ``pairs`` of the robot's links count only if apart now
        (asked when one touches at a candidate), or always if ``apart`` says they are."""
        world = robot.world
        model = robot.description.model
        body = world.object(robot.name)
        joints = world.joint_states(body)
        held = world.snapshots.held_joints(body)
        carried = set(world.bodies.attachments(body))
        ignore = [o for o in world.objects() if o.name in carried or o.type == "floor"]
        carries_more = any(a.robot in carried for a in world.bodies.all_attachments())
        return cls(
            robot,
            distance,
            world.versions.body(body),
            {j: v for j, v in joints.items() if model.joints[j].mimic is None},
            frozenset(j for j, v in joints.items() if held.get(j) != v),
            ignore,
            not carries_more,
            pairs,
            dict.fromkeys(pairs, False) if apart else {},
        )

    def holds(self) -> bool:
        """Whether the robot stands as it did at the start (base and joints), or where the
        last candidate left it, to be put back (:meth:`put_back`)."""
        return bool(self._dirty) or self.robot.world.versions.body(self.robot.name) == self.stamp

    def settled(self) -> None:
        """The robot stands as at the start again, put back by the check's own writes (a
        candidate's joints, a moved base): what it reads now is what the start read."""
        self.stamp = self.robot.world.versions.body(self.robot.name)

    def colliding(
        self,
        joints: Mapping[str, float],
        allowed: set[str],
        base_moves: bool,
        defer: bool = False,
        hand: HandContact | None = None,
        judge: Callable[[list[LinkPair]], None] | None = None,
    ) -> list[LinkPair]:
        """The ``(robot link, object)`` and self pairs in contact at ``joints``, links in
        ``allowed`` and the ``hand`` on what it acts on within its bound excepted;
        ``base_moves``: every link moved. The robot is put back after, or with ``defer``
        left there until the next candidate or :meth:`put_back`. ``judge`` is shown the
        object pairs, if any, while the robot stands at the candidate (it may raise)."""
        world = self.robot.world
        body = world.object(self.robot.name)
        moved, pairs = self._moved(body, tuple(joints), base_moves or not self.alone)
        before = self._to_restore(joints)
        masters = self.robot.description.model.derived(_MovedLinks).masters
        if not masters.isdisjoint(before):  # followers come back with masters, maybe elsewhere
            self.put_back()
            self._touching_at_start(pairs)
            defer = False
        if any(j not in joints and j not in self.unheld for j in self._dirty):
            self.put_back()  # an earlier candidate moved joints this one leaves
        carry = not self.alone  # what the robot holds carries more, which may hit it
        world.set_joint_states(body, dict(joints), carry)
        if defer:
            self._dirty.update(before)
        try:
            hits, touching = self._contacts(body, moved, pairs, allowed, base_moves)
            if hand is not None:  # measured while the robot stands at the candidate
                for link, named in [p for p in hits if hand.covers(*p)]:
                    if contact_depth(world, body, link, named) <= hand.depth:
                        del hits[(link, named)]
            if judge is not None and hits:
                judge(list(hits))
        finally:
            if not defer:
                world.set_joint_states(body, before, carry)
                self.settled()
        if any(p not in self._at_start for p in touching):
            self.put_back()  # the start's self contacts are asked where it stands
        hits.update(dict.fromkeys(p for p in touching if not self._touching_at_start([p])))
        return list(hits)

    def put_back(self) -> None:
        """Put back what deferred candidates moved (nothing if none is left)."""
        if self._dirty:
            body = self.robot.world.object(self.robot.name)
            self.robot.world.set_joint_states(body, self._dirty, not self.alone)
            self._dirty = {}
            self.settled()

    def _contacts(
        self,
        body: WorldObject,
        moved: frozenset[int],
        pairs: list[LinkPair],
        allowed: set[str],
        base_moves: bool,
    ) -> tuple[dict[LinkPair, None], list[LinkPair]]:
        """What the robot, set to a candidate, touches (links in ``allowed`` excepted), and
        which of ``pairs`` touch; each link's bounds read once for both."""
        world = self.robot.world
        colliders = body.collider_names()
        bounds = {i: b for i, b in self._bounds.items() if i not in moved}  # still where read
        bounds.update(link_bounds(world, body, [i for i in colliders if i not in bounds]))
        ask = [n for i, n in colliders.items() if i in moved or n not in self._kept]
        found: dict[str, list[LinkPair]] = {n: [] for n in ask}
        kept = world.contacts.obstacle_boxes([body, *self.ignore])  # links near nothing: unasked
        for link, obj, other in link_pairs_in_contact(
            world, body, self.ignore, self.distance, ask, None, bounds, kept
        ):
            several = len(obj.link_index) > 1
            found[link].append((link, f"{obj.name}/{other}" if several else obj.name))
        if self.alone and not base_moves:
            still = [(i, n) for i, n in colliders.items() if i not in moved]
            self._kept.update((n, found[n]) for _, n in still if n in found)
            self._bounds = {i: bounds[i] for i, _ in still}
        hits: dict[LinkPair, None] = {}
        resting = self.alone and not base_moves  # links it leaves where they were
        for i, link in colliders.items():
            if link not in allowed:
                touched = found[link] if link in found else self._kept[link]
                if resting and i not in moved:
                    touched = [p for p in touched if not self._rests_on(body, link, p[1])]
                hits.update(dict.fromkeys(touched))
        return hits, self_contacts(world, body, pairs, self.distance, bounds)

    def _rests_on(self, body: WorldObject, link: str, other: str) -> bool:
        """Whether the one-link object ``other`` rests on ``link`` of the robot, which the
        candidate does not move (a mug on the robot's own table top): every contact's
        normal points up out of the link. Such a contact is the start's, not a collision."""
        world = self.robot.world
        if "/" in other:
            return False
        points = world.contacts.contact_points(other, body, None, link, self.distance)
        return bool(points) and all(p.normal_on_b[2] >= RESTING for p in points)

    def _touching_at_start(self, pairs: list[LinkPair]) -> bool:
        """Whether any of ``pairs`` touch at the start (the robot stands there now)."""
        unknown = [p for p in pairs if p not in self._at_start]
        if unknown:
            body = self.robot.world.object(self.robot.name)
            touching = set(self_contacts(self.robot.world, body, unknown, self.distance))
            self._at_start.update((p, p in touching) for p in unknown)
            self._touching |= touching
        return any(self._at_start[p] for p in pairs)

    def _moved(
        self, body: WorldObject, joints: tuple[str, ...], everything: bool
    ) -> tuple[frozenset[int], list[LinkPair]]:
        """The link indices ``joints`` move (all if ``everything``), and the self pairs one
        of whose links moves (the others stay as at the start), those known to touch there
        left out."""
        key = () if everything else joints
        found = self._moves.get(key)
        if found is None:
            moves = self.robot.description.model.derived(_MovedLinks)
            found = self._moves[key] = moves.of(body, None if everything else joints, self.pairs)
        if self._touching:
            return found[0], [p for p in found[1] if p not in self._touching]
        return found

    def _to_restore(self, joints: Mapping[str, float]) -> dict[str, float]:
        """The values that put the robot back after it is set to ``joints``: those the
        candidate changes (mimic masters for their followers), and those simulation does
        not hold where they are (putting them back holds them there)."""
        model = self.robot.description.model
        mimics = (model.joints[j].mimic for j in joints)
        masters = {mimic.joint for mimic in mimics if mimic is not None}
        return {
            joint: value for joint, value in self.joints.items()
            if joint in joints or joint in masters or joint in self.unheld
        }  # fmt: skip


@dataclass
class _MovedLinks:
    """Per set of joints: the links below them and below their mimic followers. They
    follow from the model alone, so they are kept with it (``RobotModel.derived``)."""

    model: RobotModel
    _children: dict[str, list[str]] = field(default_factory=dict)
    _followers: dict[str, list[str]] = field(default_factory=dict)
    _found: dict[tuple[str, ...], frozenset[str]] = field(default_factory=dict)
    _pairs: dict[tuple[object, ...], tuple[frozenset[int], list[LinkPair]]] = field(
        default_factory=dict
    )

    masters: frozenset[str] = frozenset()  # the joints mimic joints follow

    def __post_init__(self) -> None:
        for name, joint in self.model.joints.items():
            self._children.setdefault(joint.parent, []).append(joint.child)
            if joint.mimic is not None:
                self._followers.setdefault(joint.mimic.joint, []).append(name)
        self.masters = frozenset(self._followers)

    def of(
        self, body: WorldObject, joints: tuple[str, ...] | None, pairs: list[LinkPair]
    ) -> tuple[frozenset[int], list[LinkPair]]:
        """The link indices of ``body`` that ``joints`` move (None: all, the base moves),
        and those of ``pairs`` (link names) one of whose links moves."""
        key = (joints, *pairs)
        found = self._pairs.get(key)
        if found is None:
            index = body.link_index
            if joints is None:
                indices = frozenset(index.values())
            else:
                indices = frozenset(index[n] for n in self.below(joints) if n in index)
            moving = [(a, b) for a, b in pairs if index[a] in indices or index[b] in indices]
            found = self._pairs.setdefault(key, (indices, moving))
        return found

    def below(self, joints: tuple[str, ...]) -> frozenset[str]:
        """The links that move when ``joints`` do."""
        found = self._found.get(joints)
        if found is None:
            moving = list(joints)
            for joint in moving:
                moving.extend(self._followers.get(joint, ()))
            links = [self.model.joints[j].child for j in moving if j in self.model.joints]
            for link in links:
                links.extend(self._children.get(link, ()))
            found = self._found.setdefault(joints, frozenset(links))
        return found

"""Configuration checks on the projection world itself (PyBullet), for a few joints.

The robot is put at each configuration, asked for contacts through Bullet's broadphase,
and put back. Held objects are checked against the world too (they ride with the hand);
the robot touching what it holds, the contacts its description allows
(``allowed_contacts``: anything on the floor), contacts the motion starts with
(``allowed_pairs``) and the ``allowed_links`` do not count; the hand of CRAM's
``allow_hand`` (a :class:`~robocram.motion.hand_contact.HandContact`) may touch only what it
acts on, no deeper than its bound. A held tool's contacts (``contacts``: a sponge on the
table, a knife in the bread it cuts) are allowed by name, each up to its own depth.
Slower than a coal snapshot, but it sees exactly what projection sees: it checks straight
segments and tool lines, and tests use it as the judge of planned paths.
"""

from __future__ import annotations

import contextlib
from collections.abc import Collection, Iterator, Mapping, Sequence
from functools import partial

import numpy as np
from numpy.typing import NDArray

from robocram.motion.allowed_contacts import AllowedContacts, Other
from robocram.motion.configuration_checker import Configuration, LinkPair
from robocram.motion.contact_allowance import ContactAllowance
from robocram.motion.errors import MotionError
from robocram.motion.hand_contact import HandContact, contact_depth
from robocram.motion.joint_levers import LeverData, cross, links_below
from robocram.motion.joint_trajectory import FloatArray
from robocram.world import Derived, ObstacleBoxes, RobotHandle, Versions, World, WorldObject

CLEARANCE_REACH = 0.1  # [m] distances asked for: a free configuration clears this much
KEPT_RULES = 32  # judges' rules and moving links kept per world (per joints, allowed links)


class BulletScene:
    """Checks configurations of ``joints`` of ``robot`` in its world (one thread at a time)."""

    def __init__(
        self,
        robot: RobotHandle,
        joints: Sequence[str],
        allowed_links: Collection[str] = (),
        distance: float = 0.0,
        allowed_pairs: Collection[LinkPair] = (),
        hand: HandContact | None = None,
        contacts: Collection[ContactAllowance] = (),
    ) -> None:
        world = robot.world
        self.world = world
        self.contacts = tuple(contacts)  # held objects' named contacts, each bounded
        self.hand = hand  # the hand's bounded contact (allow_hand), None: no such contact
        self.robot = robot.name
        self.handle = robot  # the robot the scene is of (its name is ``robot``)
        self._joints = tuple(joints)
        known = world.joint_states(robot.name)
        unknown = [j for j in self._joints if j not in known]
        if unknown:
            raise MotionError(
                f"joints {unknown} are not movable joints of {robot.name}; known: {sorted(known)}"
            )
        self.allowed_links = frozenset(allowed_links)
        key = (robot.name, self._joints, self.allowed_links)
        found = world.derived(_kept_rules).get(key, partial(_rules, robot, key), world.versions)
        self.rules = found[0]
        self.allowed_pairs = frozenset(allowed_pairs)  # (robot link | held object, other)
        self.distance = distance  # [m] nearer than this counts as touching
        self.moving_links = found[1]
        self._measured = tuple(  # the links clearances are measured of
            link for link in self.moving_links if link not in self.allowed_links
        )  # fmt: skip
        self._posed = False
        self._obstacles: ObstacleBoxes | None = None  # read once per posed block
        self._others: tuple[list[WorldObject], list[WorldObject]] | None = None  # too
        self._levers: LeverData | None = None  # what joint_levers needs, read once
        # per (robot link, other's name, type and link, whether it has several links): the
        # pair's verdict (:meth:`_verdict`); it follows from what the scene was made with
        self._verdicts: dict[tuple[str, str, str, str, bool], tuple[bool, bool]] = {}
        self._anywhere: dict[tuple[str, str], bool] = {}  # per (name, type): anywhere()'s

    @property
    def reach(self) -> float:
        """How far [m] clearance queries look (:data:`CLEARANCE_REACH`)."""
        return CLEARANCE_REACH

    @property
    def joints(self) -> tuple[str, ...]:
        """The joints a configuration gives values for, in order."""
        return self._joints

    def colliding(self, q: Configuration, first_only: bool = False) -> list[LinkPair]:
        """The colliding ``(robot link, other)`` pairs at ``q`` (empty: free)."""
        values = dict(zip(self._joints, (float(v) for v in q), strict=True))
        return self.colliding_at(values, first_only)

    @contextlib.contextmanager
    def posed(self) -> Iterator[None]:
        """Inside the block, checks leave the robot where they put it (no put-back after
        each, half their cost); the robot is put back once, when the block ends."""
        if self._posed:
            yield
            return
        before = self._current()
        self._posed = True
        try:
            yield
        finally:
            self._posed = False
            self._obstacles = None
            self._others = None
            self.world.set_joint_states(self.robot, before)

    def _others_now(self) -> tuple[list[WorldObject], list[WorldObject]]:
        """What the robot holds and what it may touch anywhere: inside a posed block only
        this robot's joints move, so they are read once per block."""
        others = self._others
        if others is None:
            world = self.world
            held = [world.object(name) for name in world.bodies.attachments(self.robot)]
            others = (held, self.anywhere())
            if self._posed:
                self._others = others
        return others

    def _obstacles_now(self, held: list[WorldObject], anywhere: list[WorldObject]) -> ObstacleBoxes:
        """The others' bounds: inside a posed block only this robot's joints move, so they
        are read once per block."""
        if self._obstacles is None:
            self._obstacles = self.world.contacts.obstacle_boxes([self.robot, *held, *anywhere])
        return self._obstacles

    def _current(self) -> dict[str, float]:
        world = self.world
        model = self.handle.model
        return {
            j: v for j, v in world.joint_states(self.robot).items() if model.joints[j].mimic is None
        }

    def colliding_at(self, values: Mapping[str, float], first_only: bool = False) -> list[LinkPair]:
        """The colliding pairs with the joints in ``values`` set (the others unchanged)."""
        with self.posed():
            self.world.set_joint_states(self.robot, values)
            return self.colliding_now(first_only)

    def is_free(self, q: Configuration) -> bool:
        """Whether ``q`` collides with nothing."""
        return not self.colliding(q, first_only=True)

    def clearance(self, q: Configuration, reach: float = CLEARANCE_REACH) -> float:
        """How far [m] the moving links (and what they hold) are from anything they may not
        touch, at ``q``; ``reach`` when nothing is nearer, 0 or less when they touch."""
        values = dict(zip(self._joints, (float(v) for v in q), strict=True))
        with self.posed():
            self.world.set_joint_states(self.robot, values)
            return self._clearance_now(reach)

    def clearance_now(self, reach: float = CLEARANCE_REACH) -> float:
        """:meth:`clearance` of the robot as it stands (no joints set and put back)."""
        return self._clearance_now(reach)

    def clearances_now(self, reach: float = CLEARANCE_REACH) -> dict[str, float]:
        """:meth:`clearances` of the robot as it stands (no joints set and put back)."""
        return self._clearances_now(reach)

    def clearances(self, q: Configuration, reach: float = CLEARANCE_REACH) -> dict[str, float]:
        """Per moving link (or held object) nearer than ``reach`` [m] to something it may
        not touch, at ``q``: that distance [m] (0 or less: touching). Links not named are
        clear by ``reach`` at least."""
        values = dict(zip(self._joints, (float(v) for v in q), strict=True))
        with self.posed():
            self.world.set_joint_states(self.robot, values)
            return self._clearances_now(reach)

    def lever_links(self) -> tuple[str, ...]:
        """The moving links that can collide (they have shapes and are not allowed to
        touch anything: a frame without shapes need not slow a sweep) and the objects
        held by a moving link (they ride on it); what the other hand holds stays put."""
        moving = set(self.moving_links)
        handle = self.handle.body
        held = self.world.bodies.attachments(self.robot)
        shaped = (
            link for link in self.moving_links
            if link not in self.allowed_links
            and handle.link_index.get(link, -2) in handle.colliders
        )  # fmt: skip
        return (*shaped, *(obj for obj, link in held.items() if link in moving))

    def joints_after(self) -> NDArray[np.bool_]:
        """``[i, k]``: whether joint k's child link moves with joint i (k below i)."""
        return self.lever_data().after

    def joint_levers(self, links: Sequence[str]) -> FloatArray:
        """Per link of ``links`` (a moving link, or a held object: its carrier), per joint:
        the most [m] a point of the link moves per unit change of the joint, as the robot
        is posed now (the distance from the joint's axis to the link's frame plus the
        link's radius; 1 for a prismatic joint; 0 for joints above which it is not).

        Far tighter than :class:`TravelBound`'s levers, which hold whatever the other joints
        do: a folded arm's hand is near the shoulder's axis, not an arm's length away.
        """
        data = self.lever_data()
        frames = np.array(self.world.bodies.link_frames(self.robot, data.frame_links))
        joints = frames[data.joint_rows]
        axes = _rotated(joints[:, 3:], data.local_axes)  # (joints, 3)
        return data.levers(links, frames[:, :3], joints[:, :3], axes)

    def link_speeds(self, links: Sequence[str], delta: FloatArray) -> FloatArray:
        """Per link of ``links``: the most [m] a point of it moves per unit of a segment
        whose joints change by ``delta``, as the robot is posed now (its frame's speed
        plus its angular speed times its radius; see :meth:`LeverData.speeds`)."""
        data = self.lever_data()
        frames = np.array(self.world.bodies.link_frames(self.robot, data.frame_links))
        joints = frames[data.joint_rows]
        axes = _rotated(joints[:, 3:], data.local_axes)  # (joints, 3)
        return data.speeds(links, frames[:, :3], joints[:, :3], axes, delta)

    def lever_data(self) -> LeverData:
        """What :meth:`joint_levers` needs beyond the frames, read once."""
        if self._levers is None:
            self._levers = LeverData.of(self.handle, self._joints, self.moving_links)
        return self._levers

    def _clearance_now(self, reach: float) -> float:
        return min(self._clearances_now(reach).values(), default=reach)

    def _clearances_now(self, reach: float) -> dict[str, float]:
        world = self.world
        held, anywhere = self._others_now()
        gaps: dict[str, float] = {}
        links = self._measured
        boxes = self._obstacles_now(held, anywhere)
        for link, obj, other_link, gap in world.contacts.link_distances(
            self.robot, [*held, *anywhere], reach, links=links, obstacles=boxes
        ):
            counts, bounded = self._verdict(link, obj, other_link)
            if counts:
                gaps[link] = min(gaps.get(link, reach), gap - self.distance)
            elif bounded:  # clear until deeper than the bound
                assert self.hand is not None
                gap += self.hand.depth
                gaps[link] = min(gaps.get(link, reach), gap - self.distance)
        for item in held:
            skip = [self.handle.body, *(h for h in held if h is not item), *anywhere]
            for _, obj, other_link, gap in world.contacts.link_distances(
                item, skip, reach, obstacles=boxes
            ):
                if (item.name, _named(world, obj, other_link)) not in self.allowed_pairs:
                    gap += self._tool_depth(item.name, obj, other_link)  # clear until deeper
                    gaps[item.name] = min(gaps.get(item.name, reach), gap - self.distance)
        return gaps

    def _tool_depth(self, held: str, obj: WorldObject, other_link: str) -> float:
        """How deep [m] held object ``held`` may go into ``obj`` by the named contacts
        (0: not at all)."""
        return max(
            (c.depth for c in self.contacts if c.covers(held, obj.name, other_link)), default=0.0
        )

    def _tool_too_deep(self, held: WorldObject, obj: WorldObject, other_link: str) -> bool:
        """Whether ``held`` is deeper in ``obj`` than its named contacts allow (any
        contact at all when none names the pair)."""
        bound = self._tool_depth(held.name, obj, other_link)
        if bound <= 0.0:
            return True
        points = self.world.contacts.contact_points(held, obj, None, other_link or None, 0.0)
        return max((-p.distance for p in points), default=0.0) > bound

    def _verdict(self, link: str, obj: WorldObject, other_link: str) -> tuple[bool, bool]:
        """(:meth:`_counts`, :meth:`_bounded`) of robot ``link`` touching ``other_link`` of
        ``obj``: both follow from the scene's rules, allowed pairs and hand (fixed when it
        was made) and the other's name, type and link, so each pair is judged once."""
        key = (link, obj.name, obj.type, other_link, len(obj.link_index) > 1)
        found = self._verdicts.get(key)
        if found is None:
            found = self._verdicts[key] = (
                self._counts(link, obj, other_link),
                self._bounded(link, obj, other_link),
            )
        return found

    def _counts(self, link: str, obj: WorldObject, other_link: str) -> bool:
        """Whether robot ``link`` touching ``obj`` is a collision (rules, start contacts,
        the hand on what it acts on: :meth:`_bounded`)."""
        if self.rules.allows(link, Other(obj.name, obj.type)):
            return False
        named = _named(self.world, obj, other_link)
        if (link, named) in self.allowed_pairs:
            return False
        return self.hand is None or not self.hand.covers(link, named)

    def _bounded(self, link: str, obj: WorldObject, other_link: str) -> bool:
        """Whether robot ``link`` touching ``obj`` is the hand's contact, a collision only
        deeper than its bound (not a contact allowed otherwise)."""
        if self.hand is None or self.rules.allows(link, Other(obj.name, obj.type)):
            return False
        named = _named(self.world, obj, other_link)
        return (link, named) not in self.allowed_pairs and self.hand.covers(link, named)

    def _too_deep(self, link: str, obj: WorldObject, other_link: str) -> bool:
        """Whether the hand's ``link`` is deeper in ``obj`` than its contact allows."""
        assert self.hand is not None
        named = _named(self.world, obj, other_link)
        return contact_depth(self.world, self.robot, link, named) > self.hand.depth

    def anywhere(self) -> list[WorldObject]:
        """Objects every link may touch by the description's rules (the floor)."""
        return [o for o in self.world.objects() if o.name != self.robot and self._free_to(o)]

    def _free_to(self, obj: WorldObject) -> bool:
        """Whether the rules let every link touch ``obj``: asked once per name and type."""
        key = (obj.name, obj.type)
        found = self._anywhere.get(key)
        if found is None:
            found = self._anywhere[key] = self.rules.allows_any_link(Other(obj.name, obj.type))
        return found

    def colliding_now(self, first_only: bool = False) -> list[LinkPair]:
        """The colliding pairs of the robot (and what it holds) as it is in the world now."""
        world = self.world
        held, anywhere = self._others_now()
        hits: dict[LinkPair, None] = {}
        boxes = self._obstacles_now(held, anywhere) if self._posed else None
        for link, obj, other_link in world.contacts.link_pairs_in_contact(
            self.robot, [*held, *anywhere], self.distance, links=self.moving_links,
            obstacles=boxes,
        ):  # fmt: skip
            counts, bounded = self._verdict(link, obj, other_link)
            if counts or (bounded and self._too_deep(link, obj, other_link)):
                hits[(link, _named(world, obj, other_link))] = None
                if first_only:
                    return list(hits)
        for item in held:
            skip = [self.handle.body, *(h for h in held if h is not item), *anywhere]
            for _, obj, other_link in world.contacts.link_pairs_in_contact(
                item, skip, self.distance, obstacles=boxes
            ):
                pair = (item.name, _named(world, obj, other_link))
                if pair not in self.allowed_pairs and self._tool_too_deep(item, obj, other_link):
                    hits[pair] = None
                    if first_only:
                        return list(hits)
        return list(hits)


def _rotated(quaternions: FloatArray, vectors: FloatArray) -> FloatArray:
    """Each vector turned by its quaternion ``(x, y, z, w)``, row by row."""
    q, w = quaternions[:, :3], quaternions[:, 3:4]
    t = 2.0 * cross(q, vectors)
    return vectors + w * t + cross(q, t)


def _named(world: World, obj: WorldObject, link: str) -> str:
    """An object by its name, or ``object/link`` when it has several links."""
    return f"{obj.name}/{link}" if len(obj.link_index) > 1 else obj.name


_JudgeKey = tuple[str, tuple[str, ...], frozenset[str]]  # robot, joints, allowed links
_KeptRules = Derived[_JudgeKey, tuple[AllowedContacts, tuple[str, ...]]]


def _kept_rules(world: World) -> _KeptRules:
    """Per (robot, joints, allowed links): the robot's rules and its moving links, kept
    with the world while the robot's body is the same (a judge is made per motion, and
    reading them again cost a quarter of its making)."""
    return Derived(_robot_created, size=KEPT_RULES)


def _robot_created(versions: Versions, key: _JudgeKey) -> int:
    return versions.created(key[0])


def _rules(robot: RobotHandle, key: _JudgeKey) -> tuple[AllowedContacts, tuple[str, ...]]:
    """The rules of ``robot`` (named ``key[0]``) and the links moved by ``key[1]``."""
    _, joints, allowed_links = key
    rules = AllowedContacts.of(robot.description, allowed_links)
    moving = (  # only these can touch anything new; no joints: the base
        links_below(robot, joints) if joints else tuple(robot.world.link_names(robot.name))
    )
    return rules, moving

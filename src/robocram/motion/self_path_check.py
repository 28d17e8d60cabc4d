"""Keeping a robot's links apart from each other along a whole joint path.

The world checks (:mod:`segment_check`) look at what the moving links may hit around the
robot; this looks at the robot itself, for every pair its
:class:`~robocram.motion.self_collision_matrix.SelfCollisionMatrix` checks that the
planned joints move relative to each other (a forearm and its own fingers, a hand and the
torso, a parked arm and the head on a rising lift).

It walks the path by conservative advancement on PyBullet's distances between the two
links of each pair: from a checked configuration, it moves on until some pair could have
closed its gap, measured by how far the joints between the two links (not those above
both) can move a point of either (:class:`~robocram.motion.travel_bound.TravelBound`'s
rigid levers). Near contact it steps :data:`MIN_STEP` at least.

A pair touching where the motion starts (a hand folded on the torso's hull) may stay in
contact only while it does not deepen (by more than :data:`DEEPEN`); every other pair
counts from the first touch. So a motion never creates or deepens a self-collision.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import partial

import numpy as np

from robocram.logic.lru import LRUCache
from robocram.motion.coal_self_distances import SELF_MARGIN, SelfDistances, SelfParts
from robocram.motion.configuration_checker import LinkPair
from robocram.motion.held_self_pairs import held_pairs
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.robot_geometry import RobotGeometry
from robocram.motion.self_collision import active_joints, follower_fold
from robocram.motion.self_collision_matrix import SelfCollisionMatrix
from robocram.motion.travel_bound import TravelBound
from robocram.world import Derived, RobotHandle, Versions, World

REACH = 1.0  # [m] closest points are asked this far (a farther pair is clear by it)
MIN_STEP = 0.002  # [m] of a pair's relative travel between two checks near contact
DEEPEN = 0.0005  # [m] a contact a motion starts with may deepen by this (numerics)
KEPT = 32  # robots and joint sets whose pairs a world keeps


@dataclass(frozen=True)
class SelfPathCheck:
    """The self pairs one motion of ``joints`` must keep apart, with their levers."""

    robot: RobotHandle
    joints: tuple[str, ...]
    pairs: tuple[LinkPair, ...]
    levers: FloatArray  # (pairs, joints) [m per unit]: relative travel per joint change
    floors: FloatArray  # per pair [m]: nearer than this is a collision
    distances: SelfDistances  # lower bounds on the pairs' distances, from coal
    held: SelfPathCheck | None = None  # what the hands hold against the robot's links
    pybullet: bool = True  # a touching pair is measured by PyBullet (the links' own word)

    @classmethod
    def of(cls, robot: RobotHandle, joints: Sequence[str]) -> SelfPathCheck:
        """The check of a motion of ``joints`` from where the robot is now, held things
        included."""
        world = robot.world
        joints = tuple(joints)
        build = partial(_moved_pairs_once, robot, joints)
        pairs, levers, parts = world.derived(_kept_pairs).get(
            (robot.name, joints), build, world.versions
        )
        model = robot.description.model
        now = world.joint_states(robot.name)
        standing = {j: v for j, v in now.items() if model.joints[j].mimic is None}
        geometry = model.derived(RobotGeometry.of)
        distances = _self_distances(robot, geometry, parts, joints, standing)
        q = np.array([now[j] for j in joints])
        floors = _floors(robot, pairs, distances, q)
        held = _held_check(robot, joints, geometry, standing, q)
        return cls(robot, joints, pairs, levers, floors, distances, held)

    def colliding(self, q: Sequence[float]) -> list[LinkPair]:
        """The pairs colliding at ``q`` (held things' last)."""
        held = self.held.colliding(q) if self.held is not None else []
        return [*self._own_colliding(q), *held]

    def first_collision(
        self, waypoints: Sequence[Sequence[float]]
    ) -> tuple[float, list[LinkPair]] | None:
        """Where along the path through ``waypoints`` (a fraction of its segments) the
        first self-collision is found, and its pairs, held things included; None when the
        path keeps apart."""
        found = self._walk(waypoints)
        if self.held is not None:
            other = self.held.first_collision(waypoints)
            if other is not None and (found is None or other[0] < found[0]):
                found = other
        return found

    def _own_colliding(self, q: Sequence[float]) -> list[LinkPair]:
        if not self.pairs:
            return []
        posing = _Posing(self.robot, self.joints)
        try:
            gaps = self._gaps(np.asarray(q, dtype=float), np.zeros(len(self.pairs)), posing)
        finally:
            posing.restore()
        return [self.pairs[k] for k in np.flatnonzero(gaps < 0.0).tolist()]

    def _walk(self, waypoints: Sequence[Sequence[float]]) -> tuple[float, list[LinkPair]] | None:
        """:meth:`first_collision` of this check's own pairs."""
        points = np.asarray(waypoints, dtype=float)
        if not self.pairs or len(points) < 2:
            return None
        travel = np.abs(np.diff(points, axis=0)) @ self.levers.T  # (segments, pairs)
        steps = _Steps(travel)
        segment, s = 0, 0.0
        posing = _Posing(self.robot, self.joints)
        try:
            while True:
                q = points[segment] + (points[segment + 1] - points[segment]) * s
                gaps = self._gaps(q, travel[segment], posing)
                if gaps.min() < 0.0:
                    fraction = (segment + s) / (len(points) - 1)
                    return fraction, [self.pairs[k] for k in np.flatnonzero(gaps < 0.0).tolist()]
                if segment == len(points) - 2 and s >= 1.0:
                    return None
                segment, s = steps.advance(segment, s, np.maximum(gaps, MIN_STEP))
        finally:
            posing.restore()

    def _gaps(self, q: FloatArray, rate: FloatArray, posing: _Posing) -> FloatArray:
        """Per pair, at ``q``: a lower bound on how far it is from counting as a collision
        (< 0: it does). Pairs whose bounds could touch are measured exactly; the others
        in the order their bounds would limit a step at ``rate`` (travel per unit of the
        segment), until no bound left can limit it more than a measured gap does."""
        floors = self.floors
        lower = self.distances.bounds(q) - floors
        gaps = lower.copy()
        rates = rate.tolist()  # the loops below read single values: floats cost less

        def measure(k: int) -> float:
            found = self.distances.distance(k)
            if self.pybullet and self.distances.touching(found):  # PyBullet's own word
                posing.pose(q)
                found = float(
                    self.robot.world.contacts.self_distances(
                        self.robot.name, self.pairs, REACH, lambda _: (k,)
                    )[k]
                )
            gap = found - float(floors[k])
            gaps[k] = gap
            return max(gap, MIN_STEP)

        touching = np.flatnonzero(lower < 0.0).tolist()
        best = np.inf
        for k in touching:
            step = measure(k)
            if rates[k] > 0.0:
                best = min(best, step / rates[k])
        ratio = np.full(len(rate), np.inf)
        np.divide(np.maximum(lower, MIN_STEP), rate, out=ratio, where=rate > 0.0)
        for k in np.argsort(ratio, kind="stable").tolist():
            if ratio[k] >= best:
                break
            if lower[k] < 0.0:
                continue
            best = min(best, measure(k) / rates[k])
        return gaps


class _Steps:
    """Steps along a path whose pairs travel ``travel`` (segments, pairs) per segment."""

    def __init__(self, travel: FloatArray) -> None:
        self.travel = travel
        moving = travel > 0.0
        self.moving = list(moving)
        self.rates = [row[mask] for row, mask in zip(travel, moving, strict=True)]

    def advance(self, segment: int, s: float, budget: FloatArray) -> tuple[int, float]:
        """The furthest ``(segment, s)`` from here no pair can travel its ``budget`` by
        (``budget`` is spent: it is the caller's fresh array)."""
        left = budget
        travel = self.travel
        last = len(travel) - 1
        while True:
            rest = travel[segment] * (1.0 - s)
            if (rest <= left).all():
                if segment == last:
                    return segment, 1.0
                left -= rest
                segment, s = segment + 1, 0.0
                continue
            share = (left[self.moving[segment]] / self.rates[segment]).min()
            return segment, min(s + float(share), 1.0)


def _floors(
    robot: RobotHandle, pairs: tuple[LinkPair, ...], distances: SelfDistances, q: FloatArray
) -> FloatArray:
    """Per pair: nearer than this [m] is a collision; a pair touching now (at ``q``) may
    stay as deep (:data:`DEEPEN` more). PyBullet measures only the pairs coal does not
    find apart, first by their bounds, then by coal's distance (both lower bounds on
    PyBullet's distance, as the robot stands): the others' floor is -DEEPEN, as PyBullet's
    positive distance would make it."""
    world = robot.world
    floors = np.full(len(pairs), -DEEPEN)
    bounds = distances.bounds(q)
    near = [k for k in np.flatnonzero(~(bounds > 0.0)).tolist()
            if distances.touching(distances.distance(k))]  # fmt: skip
    if near:
        measured = world.contacts.self_distances(robot.name, [pairs[k] for k in near], 0.0)
        floors[near] = np.minimum(measured, 0.0) - DEEPEN
    return floors


def _held_check(
    robot: RobotHandle,
    joints: tuple[str, ...],
    geometry: RobotGeometry,
    standing: dict[str, float],
    q: FloatArray,
) -> SelfPathCheck | None:
    """The walk of the held things against the robot's links (:mod:`held_self_pairs`):
    coal's word alone (a held thing is no link PyBullet measures the robot's pairs
    between); a pair touching at ``q`` may stay as deep, as the robot's own pairs may."""
    found = held_pairs(robot, joints)
    if found is None:
        return None
    pairs, levers, parts = found
    distances = SelfDistances(geometry, parts, joints, standing, SELF_MARGIN)
    bounds = distances.bounds(q)
    floors = np.full(len(pairs), -DEEPEN)
    for k in np.flatnonzero(~(bounds > 0.0)).tolist():
        floors[k] = min(distances.distance(k), 0.0) - DEEPEN
    return SelfPathCheck(robot, joints, pairs, levers, floors, distances, pybullet=False)


_MovedPairs = tuple[tuple[LinkPair, ...], FloatArray, SelfParts]  # pairs, levers, parts
_StillKey = tuple[str, tuple[str, ...], tuple[tuple[str, float], ...]]  # robot, planned, still


def _self_distances(
    robot: RobotHandle,
    geometry: RobotGeometry,
    parts: SelfParts,
    joints: tuple[str, ...],
    standing: dict[str, float],
) -> SelfDistances:
    """The self distances of a motion of ``joints``, kept with the world per robot,
    planned joints and the values of the joints they do not set. A check sets the planned
    joints (and their followers) at every configuration and places only the parts below
    them: the other parts stand where those values put them, so a motion whose other
    joints stand as an earlier one's (a handle's next step) asks the same distances, and
    the configurations that motion measured last (the step's end: the next one's start)
    are answered as kept."""
    world = robot.world
    still = tuple((j, v) for j, v in standing.items() if j not in joints)
    build = partial(SelfDistances, geometry, parts, joints, standing, SELF_MARGIN)
    kept = world.derived(_kept_distances)
    return kept.get((robot.name, joints, still), build, world.versions)


def _kept_distances(world: World) -> Derived[_StillKey, SelfDistances]:
    """Per robot, planned joints and the other joints' values: a motion's self distances,
    kept while the robot's body is the same (its parts are the pairs' kept with it)."""
    return Derived(_still_created, size=KEPT)


def _still_created(versions: Versions, key: _StillKey) -> int:
    return versions.created(key[0])


def _kept_pairs(world: World) -> Derived[tuple[str, tuple[str, ...]], _MovedPairs]:
    """Per robot and planned joints: the pairs they move apart and their levers, kept
    with the world while the robot's body is the same (every arm motion asks; they
    change only with the description)."""
    return Derived(_robot_created, size=KEPT)


def _robot_created(versions: Versions, key: tuple[str, tuple[str, ...]]) -> int:
    return versions.created(key[0])


def _moved_pairs_once(robot: RobotHandle, joints: tuple[str, ...]) -> _MovedPairs:
    """:func:`_moved_pairs`, or those worked out from the same inputs in any world: kept
    with the model by all they follow from besides it (the matrix's pairs, the links'
    radii and PyBullet indices), so a new scene's robot does not work them out again."""
    world = robot.world
    key = (
        joints, SelfCollisionMatrix.of(robot).checked,
        tuple(world.contacts.link_radii(robot.name).items()),
        tuple(world.object(robot.name).link_index.items()),
    )  # fmt: skip
    kept = robot.description.model.derived(_pairs_of_model)
    found = kept.get(key)
    if found is None:
        found = _moved_pairs(robot, joints)
        kept.put(key, found)
    return found


def _pairs_of_model(model: object) -> LRUCache[tuple[object, ...], _MovedPairs]:
    """The moved pairs a model keeps (never changed once worked out)."""
    return LRUCache(KEPT)


def _moved_pairs(robot: RobotHandle, joints: tuple[str, ...]) -> _MovedPairs:
    """The matrix's checked pairs that ``joints`` move relative to each other, and per
    pair and joint the most a point of either link moves relative to the other per unit
    change of the joint (joints above both move neither relative to the other)."""
    model = robot.description.model
    matrix = SelfCollisionMatrix.of(robot)
    active = sorted(active_joints(model, joints))
    bound = TravelBound.of(robot, active, held=False)
    fold = follower_fold(model, active, joints)
    every = list(matrix.checked)
    geometry = model.derived(RobotGeometry.of)
    link_index = robot.world.object(robot.name).link_index
    if not every:
        return (), np.zeros((0, len(joints))), SelfParts.of(geometry, link_index, ())
    names = sorted({link for pair in every for link in pair})
    row = {link: k for k, link in enumerate(names)}
    table = np.zeros((len(names), len(active)))
    for link, lever in bound.link_lever.items():
        if link in row:
            table[row[link]] = lever
    first = table[[row[a] for a, _ in every]]
    second = table[[row[b] for _, b in every]]
    relative = np.where((first > 0.0) & (second > 0.0), 0.0, first + second) @ fold
    moved = np.flatnonzero(relative.any(axis=1))
    pairs = tuple(every[k] for k in moved.tolist())
    return pairs, relative[moved], SelfParts.of(geometry, link_index, pairs)


class _Posing:
    """Poses the robot in PyBullet only when a pair needs PyBullet's own distance, and
    puts its joints back afterwards (coal answers most checks with nothing posed)."""

    def __init__(self, robot: RobotHandle, joints: tuple[str, ...]) -> None:
        self.world, self.robot, self.joints = robot.world, robot.name, joints
        self.model = robot.description.model
        self.before: dict[str, float] | None = None
        self.at: FloatArray | None = None

    def pose(self, q: FloatArray) -> None:
        """The robot's planned joints at ``q`` in PyBullet."""
        if self.at is q:
            return
        if self.before is None:
            model = self.model
            self.before = {
                j: v for j, v in self.world.joint_states(self.robot).items()
                if model.joints[j].mimic is None
            }  # fmt: skip
        self.world.set_joint_states(
            self.robot, dict(zip(self.joints, q.tolist(), strict=True)), carry=False
        )
        self.at = q

    def restore(self) -> None:
        """The joints as they were, if any check posed them."""
        if self.before is not None:
            self.world.set_joint_states(self.robot, self.before, carry=False)
            self.before = self.at = None

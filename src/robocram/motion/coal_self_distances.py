"""Lower bounds on the distances between a robot's own links, from coal and pinocchio.

The self walk (:mod:`~robocram.motion.self_path_check`) asks about ten times per motion
how far each checked pair of links is apart. PyBullet answers only after the robot is
posed in it (~50 us to place every link), the links' bounds are read and closest points
asked: ~0.3 ms a check, a quarter of a kitchen transport's time. Here pinocchio places
only the pairs' parts (the same convex pieces PyBullet collides,
:mod:`~robocram.motion.robot_geometry`), their bounding balls bound every pair at once,
and coal measures the pairs the walk picks.

Coal's distance less :data:`SELF_MARGIN` never exceeds PyBullet's between two links
apart; touching or penetrating, coal's depth says nothing about PyBullet's, so the walk
asks PyBullet itself then (:meth:`SelfDistances.touching`).
"""

from __future__ import annotations

from collections.abc import Hashable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics.robot_kinematics import RobotKinematics
from robocram.logic.lru import LRUCache
from robocram.motion.configuration_checker import LinkPair
from robocram.motion.joint_slots import JointSlots
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.robot_geometry import Part, RobotGeometry
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import coal
    import pinocchio as pin
else:
    coal = LazyLibrary("coal")
    pin = LazyLibrary("pinocchio")

# [m] PyBullet grows each of two hulls by its 1 mm collision margin: its distance between
# two of a robot's links is coal's less 2.0 mm (seeded PR2, HSR and Boxy arm poses: 1.9 to
# 2.01 mm), and its GJK errs by up to ~0.7 mm more (:mod:`coal_clearance`)
SELF_MARGIN = 0.003
NO_PARTS = -np.inf  # the bound of a pair coal has no parts for: PyBullet must measure it
KEPT_POSES = 4  # configurations whose bounds and distances a motion's check keeps


@dataclass(frozen=True)
class SelfParts:
    """The parts of a set of link pairs as arrays: per pair, the pairs of parts between
    its two links (all of a PyBullet link's parts: those of the links folded into it)."""

    parts: tuple[Part, ...]
    joints: list[int]  # the pinocchio joints the parts ride on
    part_row: NDArray[np.intp]  # per part: its joint's row in ``joints``
    centres: FloatArray  # (parts, 4) each part's ball centre in its joint's frame, 1
    boxes: FloatArray  # (parts, 3, 3) its box's axes scaled by its half extents, there
    radii: FloatArray  # (parts,) [m]
    first: NDArray[np.intp]  # per part pair: its first part
    second: NDArray[np.intp]  # and its second
    sums: FloatArray  # per part pair: the two balls' radii summed
    starts: NDArray[np.intp]  # per link pair: where its part pairs start (reduceat)
    empty: NDArray[np.bool_]  # per link pair: coal has no parts for one of its links
    single: bool  # every link pair has one pair of parts: the per-pair minimum is a no-op
    _moved: dict[tuple[str, ...], _Moving] = field(default_factory=dict, compare=False)
    _part_pairs: dict[int, list[tuple[int, int]]] = field(default_factory=dict, compare=False)

    def moved(self, kin: RobotKinematics, slots: JointSlots) -> _Moving:
        """For motions of ``slots``' joints: the joints they move and the parts riding on
        them, as a check reads them (kept: every motion of those joints asks)."""
        found = self._moved.get(slots.names)
        if found is None:
            rows = _moved_rows(kin, slots, self.joints)
            found = self._moved[slots.names] = _Moving.of(self, rows)
        return found

    def part_pairs(self, k: int) -> list[tuple[int, int]]:
        """Link pair ``k``'s pairs of parts (kept: a walk measures a pair many times)."""
        found = self._part_pairs.get(k)
        if found is None:
            end = self.starts[k + 1] if k + 1 < len(self.starts) else len(self.first)
            found = self._part_pairs[k] = list(
                zip(
                    self.first[self.starts[k] : end].tolist(),
                    self.second[self.starts[k] : end].tolist(),
                    strict=True,
                )
            )
        return found

    @classmethod
    def of(
        cls, geometry: RobotGeometry, pybullet_link: dict[str, int], pairs: Sequence[LinkPair]
    ) -> SelfParts:
        """The parts of ``pairs``; ``pybullet_link`` gives each link's index in the
        projection world's body (links folded into a host share the host's)."""
        pieces: dict[Hashable, list[Part]] = {}
        for link, own in geometry.parts.items():
            index = pybullet_link.get(link)
            if index is not None:
                pieces.setdefault(index, []).extend(own)
        return cls.grouped(pieces, pybullet_link, pairs)

    @classmethod
    def grouped(
        cls,
        pieces: Mapping[Hashable, Sequence[Part]],
        group_of: Mapping[str, Hashable],
        pairs: Sequence[LinkPair],
    ) -> SelfParts:
        """The parts of ``pairs`` whose names ``group_of`` maps to groups of ``pieces``
        (a PyBullet link's parts; or a held object's, riding on its carrier's joint)."""
        parts: list[Part] = []
        where: dict[Hashable, list[int]] = {}
        for index, found in pieces.items():
            where[index] = list(range(len(parts), len(parts) + len(found)))
            parts.extend(found)
        first: list[int] = []
        second: list[int] = []
        starts: list[int] = []
        empty: list[bool] = []
        for a, b in pairs:
            one, two = where.get(group_of[a], []), where.get(group_of[b], [])
            starts.append(len(first))
            empty.append(not one or not two)
            if empty[-1]:  # a placeholder part pair keeps reduceat's rows one per pair
                one, two = [0], [0]
            for m in one:
                for n in two:
                    first.append(m)
                    second.append(n)
        joints = sorted({p.joint for p in parts})
        row = {j: k for k, j in enumerate(joints)}
        radii = np.array([p.radius for p in parts], dtype=float).reshape(-1)
        centres = np.ones((len(parts), 4))
        boxes = np.zeros((len(parts), 3, 3))
        if parts:
            centres[:, :3] = np.array([p.centre for p in parts], dtype=float)
            boxes[:] = np.array([p.axes * p.halves[None, :] for p in parts], dtype=float)
        firsts = np.array(first, dtype=np.intp)
        seconds = np.array(second, dtype=np.intp)
        return cls(
            tuple(parts),
            joints,
            np.array([row[p.joint] for p in parts], dtype=np.intp),
            centres,
            boxes,
            radii,
            firsts,
            seconds,
            radii[firsts] + radii[seconds] if parts else np.zeros(len(firsts)),
            np.array(starts, dtype=np.intp),
            np.array(empty, dtype=bool),
            starts == list(range(len(first))),
        )


@dataclass(frozen=True)
class _Moving:
    """What a check of some planned joints reads: the rows of :attr:`SelfParts.joints`
    they move (pinocchio ``ids``), the parts riding on those, and per such part its
    joint's position among the rows, its ball centre (4, 1) and its scaled box axes."""

    rows: NDArray[np.intp]
    ids: list[int]
    parts: NDArray[np.intp]
    carrier: NDArray[np.intp]
    centres: FloatArray  # (moved parts, 4, 1)
    boxes: FloatArray  # (moved parts, 3, 3)
    parts_set: frozenset[int]  # ``parts``

    @classmethod
    def of(cls, parts: SelfParts, rows: NDArray[np.intp]) -> _Moving:
        moved = np.flatnonzero(np.isin(parts.part_row, rows))
        position = {row: k for k, row in enumerate(rows.tolist())}
        carrier = np.array([position[r] for r in parts.part_row[moved].tolist()], dtype=np.intp)
        return cls(
            rows,
            [parts.joints[k] for k in rows.tolist()],
            moved,
            carrier,
            parts.centres[moved][:, :, None],
            parts.boxes[moved],
            frozenset(moved.tolist()),
        )


class SelfDistances:
    """One motion's self distances: the robot's other joints stay as they were when it
    was made, the planned ``joints`` take each check's values."""

    def __init__(
        self,
        geometry: RobotGeometry,
        parts: SelfParts,
        joints: Sequence[str],
        standing: dict[str, float],
        margin: float,
    ) -> None:
        kin: RobotKinematics = geometry.kinematics
        self._model = kin.model
        self._data = geometry.data()  # shared: every check runs FK before reading
        self._slots = JointSlots(kin, joints, kin.configuration(standing))
        self._parts = parts
        self._margin = margin
        self._placed: dict[int, pin.SE3] = {}  # the moved parts' poses at the last check
        self._measured: dict[int, float] = {}  # per pair: its distance at the last check
        # per configuration checked lately: its bounds, moved frames, poses and distances
        # (a walk starts where the check was made, a plan's segments share their ends)
        self._kept: LRUCache[
            bytes, tuple[FloatArray, FloatArray, dict[int, pin.SE3], dict[int, float]]
        ] = LRUCache(KEPT_POSES)
        self._still: dict[int, pin.SE3] = {}  # the other parts' poses: they never move
        self._query = (coal.DistanceRequest(), coal.DistanceResult())
        pin.forwardKinematics(self._model, self._data, self._slots.q0)
        placed = self._data.oMi.tolist()  # views: read them now
        self._frames: FloatArray = np.array(
            [placed[j].homogeneous for j in parts.joints], dtype=float
        ).reshape(-1, 4, 4)
        # only the joints below a planned one move: the others' parts are placed once
        self._moving = parts.moved(kin, self._slots)
        self._centres, self._halves = _placed_boxes(self._frames, parts, parts.part_row)

    def bounds(self, q: FloatArray) -> FloatArray:
        """Per pair, with the joints at ``q``: a lower bound [m] on PyBullet's distance
        between its links, from the parts' balls and boxes (the larger bound of the two
        per pair of parts; :data:`NO_PARTS` where coal has none)."""
        parts, moving = self._parts, self._moving
        key = np.asarray(q, dtype=float).tobytes()
        kept = self._kept.get(key)
        if kept is not None:  # the same values give the same answers, to the bit
            self._frames[moving.rows] = kept[1]
            self._placed, self._measured = kept[2], kept[3]
            return kept[0]
        pin.forwardKinematics(self._model, self._data, self._slots.full(q))
        placed = self._data.oMi.tolist()  # views: read them now
        frames = np.array([placed[j].homogeneous for j in moving.ids]).reshape(-1, 4, 4)
        self._frames[moving.rows] = frames
        self._placed = dict(self._still)
        on = frames[moving.carrier]  # each moved part's joint placement
        centres, halves = self._centres, self._halves
        centres[moving.parts] = (on @ moving.centres)[:, :3, 0]
        halves[moving.parts] = np.abs(on[:, :3, :3] @ moving.boxes).sum(axis=2)
        first, second = parts.first, parts.second
        apart = np.abs(centres[first] - centres[second])
        boxes = apart - halves[first] - halves[second]  # per axis: the boxes' gap
        np.maximum(boxes, 0.0, out=boxes)
        boxes *= boxes
        apart *= apart
        balls = np.sqrt(apart.sum(axis=1)) - parts.sums
        np.maximum(balls, np.sqrt(boxes.sum(axis=1)), out=balls)
        if parts.single:  # one pair of parts per pair: its minimum is itself
            balls -= self._margin
            lower: FloatArray = balls
        else:
            lower = np.minimum.reduceat(balls, parts.starts) - self._margin
        lower[parts.empty] = NO_PARTS
        self._measured = {}
        self._kept.put(key, (lower, frames, self._placed, self._measured))
        return lower

    def distance(self, k: int) -> float:
        """Pair ``k``'s coal distance less the margin, at the last :meth:`bounds`'s
        configuration; :data:`NO_PARTS` where coal has no parts for it."""
        parts = self._parts
        if parts.empty[k]:
            return NO_PARTS
        kept = self._measured.get(k)
        if kept is not None:
            return kept
        request, result = self._query
        best = np.inf
        geometries = parts.parts
        for m, n in parts.part_pairs(k):
            result.clear()  # a result keeps the least distance of all its calls
            found = coal.distance(
                geometries[m].geometry, self._pose(m), geometries[n].geometry, self._pose(n),
                request, result,
            )  # fmt: skip
            best = min(best, found)
        self._measured[k] = float(best) - self._margin
        return self._measured[k]

    def touching(self, distance: float) -> bool:
        """Whether a :meth:`distance` is too near for coal's word: PyBullet must measure."""
        return distance <= 0.0

    def _pose(self, m: int) -> pin.SE3:
        pose = self._placed.get(m)
        if pose is None:
            part = self._parts.parts[m]
            pose = self._placed[m] = pin.SE3(self._frames[self._parts.part_row[m]]) * part.placement
            if m not in self._moving.parts_set:
                self._still[m] = pose
        return pose


def _placed_boxes(
    frames: FloatArray,
    parts: SelfParts,
    rows: NDArray[np.intp],
    which: NDArray[np.intp] | None = None,
) -> tuple[FloatArray, FloatArray]:
    """The balls' centres and the map-aligned boxes' half extents (both (n, 3)) of the
    parts ``which`` (all by default), riding on the joints at ``rows`` of ``frames``."""
    placed = frames[rows]
    centres = parts.centres if which is None else parts.centres[which]
    boxes = parts.boxes if which is None else parts.boxes[which]
    middle = (placed @ centres[:, :, None])[:, :3, 0]
    halves = np.abs(placed[:, :3, :3] @ boxes).sum(axis=2)
    return middle, halves


def _moved_rows(kin: RobotKinematics, slots: JointSlots, joints: list[int]) -> NDArray[np.intp]:
    """The rows of ``joints`` (pinocchio joints) that the slots' values move."""
    model = kin.model
    written = {*slots.plain_idx.tolist(), *slots.cont_idx.tolist()}
    starts, parents = model.idx_qs.tolist(), model.parents.tolist()
    driven = {j for j in range(1, model.njoints) if starts[j] in written}
    rows = []
    for row, joint in enumerate(joints):
        j = joint
        while j and j not in driven:
            j = parents[j]
        if j:
            rows.append(row)
    return np.array(rows, dtype=np.intp)

"""Clearances of a motion's moving links from coal, with PyBullet kept as the judge.

Walking a joint segment by conservative advancement asks "how far is each moving link
from what it may not touch?" about thirty times; PyBullet answers in ~0.5 ms (pose the
robot, read link bounds, closest points per near pair). :class:`CoalClearance` answers
the same question from coal: pinocchio places the moving links (and what they hold), a
bound leaves out far pairs, and coal's distances decide the rest
(:mod:`clearance_pairs`). The world's other objects come from a cache kept with the world
(:mod:`obstacle_shapes`), rebuilt only for objects that moved, so a motion pays no
snapshot; the pairs come from setups kept with the world too (:mod:`clearance_setup`).
A check reads only the moved joints' placements from pinocchio, and a step's speed
bounds come from pinocchio's joint velocities.

The rules are the world checker's (:class:`~robocram.motion.bullet_scene.BulletScene`,
its ``judge``): the same links, allowed contacts, start contacts and held objects. Coal's
hulls are PyBullet's shapes without its collision margin, so each distance is lowered by
:data:`BULLET_MARGIN` and never exceeds PyBullet's; whenever a link comes that near
anything, the judge decides whether the configuration collides, as on the world itself.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics.robot_kinematics import pose_to_se3, robot_kinematics
from robocram.logic.lru import LRUCache
from robocram.motion.bullet_scene import CLEARANCE_REACH, BulletScene
from robocram.motion.clearance_pairs import NearPairs
from robocram.motion.clearance_setup import SetupCache
from robocram.motion.configuration_checker import Configuration, LinkPair
from robocram.motion.joint_levers import LeverData
from robocram.motion.joint_slots import JointSlots
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.obstacle_shapes import DRIFT
from robocram.motion.robot_geometry import RobotGeometry
from robocram.robots import RobotModel
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

# [m] PyBullet grows convex hulls by a collision margin of 1 mm and its GJK is off by up
# to ~0.7 mm more; coal's distances are lowered by this so they never exceed PyBullet's
# (tests/motion/test_motion_coal_clearance.py measures it near the kitchen counter).
BULLET_MARGIN = 0.002
POSED_KEPT = 8  # configurations a checker keeps posed: walks come back to a segment's ends
JUDGED_KEPT = 256  # the judge's answers a checker keeps: a path's ends are walked again


class CoalClearance:
    """A :class:`~robocram.motion.configuration_checker.LeverChecker` for ``judge``'s
    joints: clearances from coal, contacts decided by ``judge`` (the world itself)."""

    def __init__(self, judge: BulletScene, margin: float = BULLET_MARGIN) -> None:
        self.judge = judge
        world, robot = judge.world, judge.robot
        self._geometry = world.robot(robot).description.model.derived(RobotGeometry.of)
        kin = self._geometry.kinematics
        self._model = kin.model
        self._data = self._geometry.data()  # shared: every check runs FK before reading
        masters = {  # mimic joints follow their masters in pinocchio's configuration
            j: v for j, v in world.joint_states(robot).items()
            if kin.robot_model.joints[j].mimic is None
        }  # fmt: skip
        self._slots = JointSlots(kin, judge.joints, kin.configuration(masters))
        self._base = pose_to_se3(world.pose(robot))
        self._slack = margin + DRIFT + judge.distance  # [m] taken off every coal distance
        pin.forwardKinematics(self._model, self._data, self._slots.q0)
        setup = world.derived(SetupCache).setup(
            judge, self._geometry, self._data, self._base, margin
        )
        self._joints = setup.joints  # the pinocchio joints whose placements a check reads
        self._rows = {j: k for k, j in enumerate(setup.joints)}
        self._pairs = setup.pairs
        self._levers: tuple[NDArray[np.intp], FloatArray] | None = None  # rows, frames
        self._speeds: dict[tuple[str, ...], _LinkSpeeds] = {}  # per asked links
        self._velocity_slots = np.array([kin.joint(j).idx_v for j in judge.joints], dtype=np.intp)
        self._q = self._slots.q0  # pinocchio's configuration checked last
        self._base_matrix = self._base.homogeneous
        # the offsets come from q0 too: the setup reads the data but poses nothing
        tree = world.robot(robot).description.model.derived(_pin_tree)
        self._carriers = _Carriers.of(tree, self._data, self._slots, setup.joints)
        self._frames: FloatArray = np.zeros((len(self._joints), 4, 4))  # placements, last check
        self._last: tuple[bytes, dict[str, float]] | None = None  # q -> its clearances
        self._kept: LRUCache[bytes, tuple[FloatArray, FloatArray, NearPairs]] = LRUCache(
            POSED_KEPT
        )  # q -> posed
        self._judged: LRUCache[tuple[bytes, bool], list[LinkPair]] = LRUCache(JUDGED_KEPT)

    @property
    def joints(self) -> tuple[str, ...]:
        """The joints a configuration gives values for, in order."""
        return self.judge.joints

    @property
    def reach(self) -> float:
        """How far [m] clearance queries look (:data:`CLEARANCE_REACH`)."""
        return CLEARANCE_REACH

    def clearance(self, q: Configuration) -> float:
        """The distance [m] from the moving links to what they may not touch (<= 0: near
        enough that the judge must be asked)."""
        values = np.asarray(q, dtype=float)
        if self._last is not None and self._last[0] == values.tobytes():
            return min(self._last[1].values(), default=CLEARANCE_REACH)
        self._last = None  # the pose changes: a kept answer no longer describes it
        return self._posed(values).least()  # the labels that can be least, measured

    def clearances(self, q: Configuration) -> dict[str, float]:
        """Per moving link (or held object) nearer than the reach to something it may not
        touch: that distance [m], never more than PyBullet's."""
        values = np.asarray(q, dtype=float)
        key = values.tobytes()
        if self._last is not None and self._last[0] == key:
            return dict(self._last[1])
        gaps = self._posed(values).gaps()
        self._last = (key, gaps)
        return dict(gaps)

    def near(self, q: Configuration) -> NearPairs:
        """The robot posed at ``q`` and its near pairs per label, before coal measures any:
        a step of conservative advancement needs only the labels that can limit it."""
        self._last = None  # the pose changes: a kept answer no longer describes it
        return self._posed(np.asarray(q, dtype=float))

    def _posed(self, values: FloatArray) -> NearPairs:
        """The robot posed at ``values``: pinocchio's configuration, the joints' frames and
        the near pairs, kept for the last :data:`POSED_KEPT` configurations (the same
        values give the same answer, to the bit)."""
        key = values.tobytes()
        kept = self._kept.get(key)
        if kept is None:
            q = self._slots.full(values)
            pin.forwardKinematics(self._model, self._data, q)
            frames = self._carriers.frames(self._data, self._base_matrix)
            kept = (q, frames, self._pairs.near(frames, self._slack, CLEARANCE_REACH))
            self._kept.put(key, kept)
        self._q, self._frames, near = kept
        return near

    def colliding(self, q: Configuration, first_only: bool = False) -> list[LinkPair]:
        """The colliding pairs at ``q``: none when coal finds everything clear, else the
        judge's answer."""
        if self.clearance(q) > 0.0:  # the least of the clearances, to the bit
            return []
        # the judge's answers are kept: a walk starts where the check of its segment's
        # end left off, and the world stands still while this checker lives
        key = (np.asarray(q, dtype=float).tobytes(), first_only)
        found = self._judged.get(key)
        if found is None:
            found = self.judge.colliding(q, first_only)
            self._judged.put(key, found)
        return list(found)

    def is_free(self, q: Configuration) -> bool:
        """Whether ``q`` collides with nothing (coal first, the judge when near)."""
        return not self.colliding(q, first_only=True)

    def lever_links(self) -> tuple[str, ...]:
        """The moving links and what they hold (the judge's)."""
        return self.judge.lever_links()

    def joints_after(self) -> NDArray[np.bool_]:
        """``[i, k]``: whether joint k's child link moves with joint i (the judge's)."""
        return self.judge.joints_after()

    def joint_levers(self, links: Sequence[str]) -> FloatArray:
        """Per link, per joint: the most [m] a point of it moves per unit joint change, at
        the configuration checked last (see :meth:`BulletScene.joint_levers`)."""
        data = self.judge.lever_data()
        return data.levers(links, *self._lever_frames())

    def link_speeds(self, links: Sequence[str], delta: FloatArray) -> FloatArray:
        """Per link: the most [m] a point of it moves per unit of a segment whose joints
        change by ``delta``, at the configuration checked last (see
        :meth:`BulletScene.link_speeds`)."""
        speeds = self._speeds.get(tuple(links))
        if speeds is None:
            data = self.judge.lever_data()
            speeds = self._speeds[tuple(links)] = _LinkSpeeds.of(self, data, links)
        velocity = np.zeros(self._model.nv)
        velocity[self._velocity_slots] = delta  # the planned joints' (as LeverData's)
        pin.forwardKinematics(self._model, self._data, self._q, velocity)
        return speeds.speeds(self._data)

    def lever_data(self) -> LeverData:
        """What the levers need beyond the frames (the judge's)."""
        return self.judge.lever_data()

    def _lever_frames(self) -> tuple[FloatArray, FloatArray, FloatArray]:
        """The frame links' origins, the joints' origins and axes at the last check."""
        data = self.judge.lever_data()
        if self._levers is None:
            found = [self._geometry.frame(link) for link in data.frame_links]
            rows = np.array([self._rows[joint] for joint, _ in found], dtype=np.intp)
            self._levers = (rows, np.array([placement for _, placement in found]))
        rows, placements = self._levers
        frames = self._frames[rows] @ placements  # (frame links, 4, 4)
        joints = frames[data.joint_rows]
        axes = np.einsum("jik,jk->ji", joints[:, :3, :3], data.local_axes)
        return frames[:, :3, 3], joints[:, :3, 3], axes


@dataclass(frozen=True)
class _LinkSpeeds:
    """The asked links' speed bounds from pinocchio's joint velocities (a joint's spatial
    velocity in its own frame, linear then angular): one matrix takes them to each link
    frame's velocity and angular velocity, in the frame of the joint it rides on (a norm
    does not depend on the frame)."""

    joints: list[int]  # the pinocchio joints whose velocities are read
    matrix: FloatArray  # (6 links, 6 joints)
    radii: FloatArray  # (links,) [m] about each link's frame (held objects included)

    @classmethod
    def of(cls, checker: CoalClearance, data: LeverData, links: Sequence[str]) -> _LinkSpeeds:
        rows = data.link_rows(links)
        placed = [checker._geometry.frame(data.frame_links[k]) for k in data.centre_rows[rows]]
        joints = sorted({joint for joint, _ in placed})
        matrix = np.zeros((6 * len(placed), 6 * len(joints)))
        for k, (joint, placement) in enumerate(placed):
            row, col = 6 * k, 6 * joints.index(joint)
            x, y, z = placement[:3, 3]  # the frame's origin p: w x p = -[p]x w
            matrix[row : row + 3, col : col + 3] = np.eye(3)
            matrix[row : row + 3, col + 3 : col + 6] = [[0.0, z, -y], [-z, 0.0, x], [y, -x, 0.0]]
            matrix[row + 3 : row + 6, col + 3 : col + 6] = np.eye(3)
        return cls(joints, matrix, np.asarray(data.radii[rows], dtype=float))

    def speeds(self, posed: pin.Data) -> FloatArray:
        """Per link: its frame's speed plus its angular speed times its radius, with
        ``posed``'s joint velocities."""
        velocities = posed.v.tolist()  # views: read them now
        stacked = np.array([velocities[j].vector for j in self.joints]).reshape(-1)
        both = (self.matrix @ stacked).reshape(-1, 2, 3)
        both *= both
        norms = np.sqrt(both.sum(axis=2))
        return np.asarray(norms[:, 0] + norms[:, 1] * self.radii, dtype=float)


@dataclass(frozen=True)
class _PinTree:
    """Pinocchio's joint tree of a model, and per (written q indices, joints) which
    joints carry them (a checker is made per motion, and its joints repeat)."""

    parents: list[int]  # per pinocchio joint: its parent
    starts: list[int]  # and its first q index
    carried: dict[tuple[tuple[int, ...], tuple[int, ...]], tuple[list[int], NDArray[np.intp]]]


def _pin_tree(model: RobotModel) -> _PinTree:
    """Pinocchio's joint tree of ``model`` (kept with it: reading it costs ~10 us)."""
    kin = robot_kinematics(model)
    return _PinTree(kin.model.parents.tolist(), kin.model.idx_qs.tolist(), {})


@dataclass(frozen=True)
class _Carriers:
    """The joints' placements from those of the joints a check moves: reading a placement
    from pinocchio costs more than composing it, and the joints between stay as they were
    when the checker was made."""

    read: list[int]  # the pinocchio joints read per check: moved ones, 0 for the root
    row: NDArray[np.intp]  # per joint of a check: its carrier's row in ``read``
    offsets: FloatArray  # (joints, 4, 4) each joint's placement in its carrier's frame

    @classmethod
    def of(cls, tree: _PinTree, data: pin.Data, slots: JointSlots, joints: list[int]) -> _Carriers:
        """For ``joints``, from ``data`` posed at ``slots.q0``."""
        key = ((*slots.plain_idx.tolist(), *slots.cont_idx.tolist()), tuple(joints))
        found = tree.carried.get(key)
        if found is None:
            found = tree.carried[key] = _carried(tree, set(key[0]), joints)
        read, row = found
        placed = data.oMi.tolist()  # views: read them now
        inverses = np.array([placed[c].inverse().homogeneous for c in read], dtype=float)
        frames = np.array([placed[j].homogeneous for j in joints], dtype=float)
        return cls(read, row, (inverses.reshape(-1, 4, 4)[row] @ frames.reshape(-1, 4, 4)))

    def frames(self, data: pin.Data, base: FloatArray) -> FloatArray:
        """(joints, 4, 4) the joints' placements in map, ``data`` posed by a check and the
        robot's base at ``base``."""
        placed = data.oMi.tolist()  # views: read them now
        carriers = base @ np.array([placed[j].homogeneous for j in self.read])
        return np.asarray(carriers[self.row] @ self.offsets, dtype=float)


def _carried(
    tree: _PinTree, written: set[int], joints: list[int]
) -> tuple[list[int], NDArray[np.intp]]:
    """The joints that move with ``written`` q indices and carry ``joints`` (0: the
    root), and per joint its carrier's row among them."""
    parents, starts = tree.parents, tree.starts
    moved = {j for j, at in enumerate(starts) if j and at in written}
    carriers = []
    for joint in joints:
        carrier = joint
        while carrier and carrier not in moved:
            carrier = parents[carrier]
        carriers.append(carrier)
    read = sorted(set(carriers))
    return read, np.array([read.index(c) for c in carriers], dtype=np.intp)

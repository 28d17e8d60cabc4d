"""CRAM's collision modes for arm motions, as IK collision checks on the projected world.

``avoid_all``: no link of the robot may touch anything (the floor and objects the robot
holds excepted). ``allow_hand``: the moving arm's hand and gripper links may touch what
the motion acts on (grasping; :class:`~robocram.motion.hand_contact.HandContact`), no
deeper than its bound. ``allow_all``: no check. A candidate configuration is tried on the
world and the joints are put back before the check returns (inside
:func:`putting_back_once`, when the query ends: the next candidate moves on from the
last), so IK never leaves the robot moved.

One check serves one IK query, while only the robot moves: the links a candidate's joints
do not move touch at every candidate what they touch where the robot stands, so what they
touch is asked once (:class:`~robocram.projection.ik_start.IKStart`).
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field

from robocram.kinematics import split_base_motion
from robocram.motion.collision_modes import COLLISION_MODES, hand_bound, hand_links
from robocram.motion.hand_contact import HandContact
from robocram.motion.self_collision_matrix import SelfCollisionMatrix
from robocram.projection.certain_miss import CertainMissJudge
from robocram.projection.errors import ProjectionError
from robocram.projection.ik_start import IKStart
from robocram.projection.navigation import base_moved_by
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import RobotModel

CONTACT_DISTANCE = 0.0  # [m] closer than this is a collision (touching counts)


def collision_check(
    robot: ProjectedRobot, arm: str, mode: str, touching: str | None = None
) -> Callable[[Mapping[str, float]], list[tuple[str, str]]] | None:
    """An IK ``collision_check`` for ``mode`` (None for ``allow_all``); under
    ``allow_hand`` the hand may touch ``touching`` (None: any object) within its bound.

    It returns the colliding ``(robot link, object)`` pairs, so a failure can name them.
    """
    mode = known_mode(arm, mode)
    if mode == "allow_all":
        return None
    return _Check(robot, arm, set(), hand_contact(robot, arm, mode, touching))


def known_mode(arm: str, mode: str) -> str:
    """``mode`` with dashes as underscores; a ProjectionError naming it and the modes
    there are if it is none of them."""
    normal = mode.replace("-", "_")
    if normal not in COLLISION_MODES:
        raise ProjectionError(
            f"unknown collision mode {normal!r} for the {arm} arm; use one of {COLLISION_MODES}"
        )
    return normal


@dataclass
class _Check:
    """``collides(candidate)``: the check of one query, reading the robot's start (its
    contacts, self pairs and the obstacles' bounds) at the first candidate, and again only
    if the robot stands otherwise at a later one."""

    robot: ProjectedRobot
    arm: str
    allowed: set[str]
    hand: HandContact | None = None  # the hand's bounded contact (allow_hand)
    _start: IKStart | None = field(default=None, repr=False)
    _once: bool = field(default=False, repr=False)  # put back after the query only
    _judge: CertainMissJudge | None = field(default=None, repr=False)  # may stop a query

    def __call__(self, candidate: Mapping[str, float]) -> list[tuple[str, str]]:
        joints, motion = split_base_motion(candidate)  # IK that moves the base too
        start = self._start
        if start is None or not start.holds():
            pairs = arm_pairs(self.robot, self.arm)
            start = self._start = IKStart.read(self.robot, CONTACT_DISTANCE, pairs)
        defer = self._once and motion is None  # a moved base goes back at every candidate
        with base_moved_by(self.robot, motion):
            hits = start.colliding(
                joints, self.allowed, motion is not None, defer, self.hand, self._judge
            )
        if motion is not None:
            start.settled()  # the base is back where the start stood
        return hits

    @contextlib.contextmanager
    def putting_back_once(self) -> Iterator[None]:
        """Inside, candidates leave the robot where they put it for the next one to move
        on from; it is put back when the block ends (returns or raises)."""
        self._once = True
        try:
            yield
        finally:
            self._once = False
            if self._start is not None:
                self._start.put_back()

    @contextlib.contextmanager
    def judged(self, judge: CertainMissJudge) -> Iterator[None]:
        """Inside, a refused candidate is shown to ``judge``, which stops the query
        (raising :class:`~robocram.projection.certain_miss.CertainMiss`) when no
        solution of it can be free."""
        self._judge = judge
        try:
            yield
        finally:
            self._judge = None


def judged(check: object, judge: CertainMissJudge) -> contextlib.AbstractContextManager[None]:
    """:meth:`_Check.judged` of a check made here; nothing for another one (or none)."""
    if isinstance(check, _Check):
        return check.judged(judge)
    return contextlib.nullcontext()


def putting_back_once(check: object) -> contextlib.AbstractContextManager[None]:
    """:meth:`_Check.putting_back_once` of a check made here; nothing for another one."""
    if isinstance(check, _Check):
        return check.putting_back_once()
    return contextlib.nullcontext()


def hand_contact(
    robot: ProjectedRobot, arm: str, mode: str, touching: str | None
) -> HandContact | None:
    """The contact ``allow_hand`` lets ``arm``'s hand make: ``touching`` (None: any
    object), within the bound; None in the other modes."""
    return hand_bound(robot.arm(arm), mode.replace("-", "_"), touching)


def allowed_links(robot: ProjectedRobot, arm: str, mode: str) -> set[str]:
    """The links that may touch things in ``mode``: the hand's for ``allow_hand``."""
    mode = mode.replace("-", "_")
    if mode != "allow_hand":
        return set()
    return hand_links(robot.arm(arm))


def arm_pairs(robot: ProjectedRobot, arm: str) -> list[tuple[str, str]]:
    """The pairs of the robot's self-collision matrix with a link of ``arm``: against the
    robot's other links and within the arm itself (a forearm against its own fingers),
    as every motion checks them. A check counts those apart where the robot starts."""
    matrix = SelfCollisionMatrix.of(robot.handle)
    first = robot.arm(arm).joints[0]
    return robot.description.model.derived(_ArmPairs).of(first, matrix.checked)


@dataclass
class _ArmPairs:
    """Per arm: the matrix's pairs with a link of it. They follow from the model alone,
    so they are kept with it (``RobotModel.derived``): IK asks for them at every query."""

    model: RobotModel
    _found: dict[tuple[str, tuple[tuple[str, str], ...]], list[tuple[str, str]]] = field(
        default_factory=dict
    )

    def of(self, first: str, pairs: tuple[tuple[str, str], ...]) -> list[tuple[str, str]]:
        """The pairs among ``pairs`` with a link of the arm whose first joint is ``first``
        (the arm's link first)."""
        key = (first, pairs)
        found = self._found.get(key)
        if found is None:
            below = _subtree(self.model, self.model.joints[first].child)
            found = self._found.setdefault(key, [
                (a, b) if a in below else (b, a) for a, b in pairs
                if a in below or b in below
            ])  # fmt: skip
        return found


def _subtree(model: RobotModel, link: str) -> set[str]:
    children: dict[str, list[str]] = {}
    for joint in model.joints.values():
        children.setdefault(joint.parent, []).append(joint.child)
    found, todo = set(), [link]
    while todo:
        item = todo.pop()
        if item not in found:
            found.add(item)
            todo.extend(children.get(item, ()))
    return found


def colliding_pairs(
    robot: ProjectedRobot,
    joints: Mapping[str, float],
    allowed_links: set[str],
    own: Sequence[tuple[str, str]] = (),
) -> list[tuple[str, str]]:
    """``(robot link, object)`` pairs in contact at ``joints``, ``allowed_links`` excepted,
    and the pairs among ``own`` that touch; the robot is put back after.

    The object is named by itself, or as ``object/link`` when it has several links.
    """
    start = IKStart.read(robot, CONTACT_DISTANCE, list(own), apart=True)
    return start.colliding(joints, allowed_links, base_moves=False)

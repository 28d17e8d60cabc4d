"""An arm motion from where the robot is to a joint goal or along a tool line, timed.

The straight joint-space segment is checked first on the world itself, by conservative
advancement on clearances (:mod:`segment_check`): coal measures them on obstacles kept
with the world and PyBullet decides every near contact
(:class:`~robocram.motion.coal_clearance.CoalClearance`), which needs no snapshot and
answers most motions in a few checks. A short segment (no point moving over
:data:`LIGHT_TRAVEL`: a gripper, a head's turn, a small torso move) needs no coal checker:
it is free at once when PyBullet finds nothing it may not touch within its travel, else it
is walked on PyBullet's clearances. When it is blocked, a detour over the obstacle
(:mod:`arm_detours`: the tool lifted at both ends) is checked the same way; only when that
is blocked too is a coal snapshot
(:class:`~robocram.motion.collision_scene.CollisionScene`) built, for OMPL's thousands of
checks; the planned path is then checked again on the world. Contacts the robot already
has when the motion starts (a hand resting on a handle) are allowed for that motion: the
links touching may move away from them. The hand of an ``allow_hand`` motion
(:class:`~robocram.motion.hand_contact.HandContact`) may touch only what it acts on, at most
its bound deep, on every way tried (OMPL's snapshot lets the hand touch what it acts on at
any depth; the world confirms the plan); the trajectory stores that allowance.

The answer is a :class:`ArmMotion`: the path, how it was found, and the timed trajectory.
Nothing moves here; projection follows the trajectory, ROS sends it.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from dataclasses import dataclass, replace

import numpy as np

from robocram.execution import checkpoint
from robocram.execution.failures import ManipulationPathBlocked
from robocram.motion.arm_detours import ToolHeight, detour_path
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.cartesian_path import cartesian_path
from robocram.motion.coal_clearance import CoalClearance
from robocram.motion.collision_scene import CollisionScene
from robocram.motion.configuration_checker import LinkPair, posed
from robocram.motion.corner_blend import blend_radii
from robocram.motion.hand_contact import HandContact, hand_at_start
from robocram.motion.held_start_contacts import split_start_contacts
from robocram.motion.joint_goal import motion_goal
from robocram.motion.joint_limits import joint_limits
from robocram.motion.joint_path import PLANNING_BUDGET, JointPath, plan_joint_path
from robocram.motion.joint_trajectory import FloatArray, JointTrajectory
from robocram.motion.segment_check import (
    CheckCounter,
    first_collision,
    segment_free,
    start_travel,
)
from robocram.motion.self_path_check import SelfPathCheck
from robocram.motion.time_parameterization import time_parameterize
from robocram.motion.travel_bound import TravelBound
from robocram.robots import LoadedDescription
from robocram.tf import Pose
from robocram.world import RobotHandle

SNAPSHOT_MARGINS = (0.0, 0.015)  # [m] planning again with a margin when the world disagrees
UNMOVED = 1e-9  # [rad | m] a joint changing less than this does not move
LIGHT_TRAVEL = 0.5  # [m] a straight segment moving no point farther is checked on the world
# alone: one PyBullet clearance (free when nothing is nearer than the travel), else a walk on
# PyBullet's, costs less than making a coal checker (a gripper, a head, a short torso move)
FAST_MARGIN = 0.01  # [m] the one clearance looks this much beyond the travel


@dataclass(frozen=True)
class ArmMotion:
    """A checked, timed arm motion; ``fraction`` of a tool line achieved (1 otherwise)."""

    path: JointPath
    trajectory: JointTrajectory
    fraction: float = 1.0


@dataclass(frozen=True)
class MotionSettings:
    """How arm motions are planned: whether to plan round obstacles, the seed, the budget."""

    plan: bool = True  # False: the straight segment only (a blocked one fails)
    seed: int = 0
    budget: int = PLANNING_BUDGET  # configurations OMPL may check
    check: bool = True  # False: no collision checks at all (CRAM's allow_all)
    period: float = 0.05  # [s] between the trajectory's samples (and at every waypoint)


def planned_joints(desc: LoadedDescription, goal: Mapping[str, float]) -> tuple[str, ...]:
    """The joints of ``goal`` a motion moves itself (mimic joints follow their masters)."""
    return tuple(j for j in goal if desc.model.joints[j].mimic is None)


def _scene(
    robot: RobotHandle,
    joints: tuple[str, ...],
    allowed: Collection[str],
    start: list[float],
    pairs: Collection[LinkPair] = (),
    hand: HandContact | None = None,
) -> CoalClearance:
    """The world checker (clearances from coal, contacts judged on the world), allowing
    ``pairs``, the ``hand``'s bounded contact and the contacts the robot (and what it
    holds) already has at the start: a hand on a handle, a held bowl still on its table."""
    judge = BulletScene(robot, joints, allowed, allowed_pairs=pairs, hand=hand)
    scene = CoalClearance(judge)
    touching = _start_contacts(scene, start, hand)
    if touching:
        scene = CoalClearance(_keeping(robot, joints, allowed, pairs, hand, touching))
    return scene


def _judge(
    robot: RobotHandle,
    joints: tuple[str, ...],
    allowed: Collection[str],
    start: list[float],
    pairs: Collection[LinkPair],
    hand: HandContact | None = None,
    judge: BulletScene | None = None,
) -> BulletScene:
    """The world itself as the checker, allowing ``pairs``, the ``hand``'s bounded contact
    and the start's contacts; ``judge`` is that checker without the start's contacts, when
    the caller made it already (its rules are read once)."""
    if judge is None:
        judge = BulletScene(robot, joints, allowed, allowed_pairs=pairs, hand=hand)
    touching = _start_contacts(judge, start, hand)
    if touching:
        judge = _keeping(robot, joints, allowed, pairs, hand, touching)
    return judge


def _keeping(
    robot: RobotHandle,
    joints: tuple[str, ...],
    allowed: Collection[str],
    pairs: Collection[LinkPair],
    hand: HandContact | None,
    touching: list[LinkPair],
) -> BulletScene:
    """The judge allowing ``pairs`` and the start's contacts ``touching``: the robot's
    links' kept, a held thing's no deeper than it starts (:mod:`held_start_contacts`)."""
    kept, bounded = split_start_contacts(robot, touching)
    return BulletScene(
        robot, joints, allowed, allowed_pairs={*pairs, *kept}, hand=hand, contacts=bounded
    )


def _start_contacts(
    checker: BulletScene | CoalClearance, start: list[float], hand: HandContact | None
) -> list[LinkPair]:
    """The contacts at ``start`` that the motion may keep: the colliding pairs. The hand's
    on what it acts on are not among them: :func:`hand_at_start` bounds them at their
    depth."""
    return checker.colliding(start)


def plan_arm_motion(
    robot: RobotHandle,
    goal: Mapping[str, float],
    *,
    allowed_links: Collection[str] = (),
    settings: MotionSettings = MotionSettings(),
    what: str = "the arm",
    kind: str = "arm",
    allowed_pairs: Collection[LinkPair] = (),
    hand: HandContact | None = None,
) -> ArmMotion:
    """A timed, collision-free motion of the joints in ``goal`` from where they are now.

    Any joints of the robot: an arm's, the torso, the head's, a gripper's (``kind``
    names the motion in its trajectory). ``allowed_pairs`` ``(robot link, other)`` may
    touch besides the contacts the motion starts with (fingers squeezing what they grip);
    ``hand`` may touch what it acts on within its bound (the trajectory stores it).

    A continuous joint turns the short way to its goal (:mod:`joint_goal`).

    Raises:
        ManipulationPathBlocked: the goal collides, or no way there was found; it names the
            colliding pairs and where along the straight path they are.
        MotionInputError: a goal value is not finite, or a continuous joint's is absurd.
    """
    world = robot.world
    desc = robot.description
    joints = planned_joints(desc, goal)
    hand = hand_at_start(world, robot.name, hand)
    current = world.joint_states(robot.name)
    start = [current[j] for j in joints]
    end = motion_goal(desc, joints, start, goal)
    limits = joint_limits(desc, joints)
    if not settings.check or _unmoved(start, end):  # nothing to check: the start is allowed
        path = JointPath(joints, (tuple(start), tuple(end)), "straight", 0)
    else:
        path = _checked_path(
            robot, joints, allowed_links, start, end, settings, what, allowed_pairs,
            hand,
        )  # fmt: skip
    trajectory = time_parameterize(
        robot.name, joints, path.waypoints, limits, kind=kind, period=settings.period
    )
    return ArmMotion(path, _with_hand(trajectory, hand))


def _with_hand(trajectory: JointTrajectory, hand: HandContact | None) -> JointTrajectory:
    """``trajectory`` storing the hand's bounded contact, for whoever audits it."""
    if hand is None:
        return trajectory
    return replace(trajectory, allowed_contacts=(*trajectory.allowed_contacts, *hand.allowances()))


def _unmoved(start: list[float], end: list[float]) -> bool:
    """Whether no joint moves (an arm parked again): contacts the motion starts with are
    allowed, so such a motion is free without a checker."""
    return all(abs(b - a) <= UNMOVED for a, b in zip(start, end, strict=True))


def _straight_checker(
    robot: RobotHandle,
    joints: tuple[str, ...],
    allowed: Collection[str],
    start: list[float],
    pairs: Collection[LinkPair],
    end: list[float],
    bound: TravelBound,
    hand: HandContact | None = None,
) -> tuple[BulletScene | CoalClearance | None, dict[str, float] | None]:
    """What checks the straight segment from ``start`` (where the robot stands) to
    ``end``: None when nothing it may not touch is as near as a point of it moves (it is
    free); the world itself for a short one; else coal's clearances. With it, per link,
    :func:`start_travel` of the segment when it was worked out here (the walk's own, the
    robot standing where it does: its judge has the same links and levers), else None."""
    travel = bound.travel(np.array(start), np.array(end))
    if travel > LIGHT_TRAVEL:
        return _scene(robot, joints, allowed, start, pairs, hand), None
    judge = BulletScene(robot, joints, allowed, allowed_pairs=pairs, hand=hand)
    clearance = judge.clearance_now(travel + FAST_MARGIN)
    if clearance > travel:
        return None, None
    # the robot stands at the start: its levers bound the travel tighter (a small step's
    # joints partly undo each other)
    travels: dict[str, float] | None = None
    if clearance > 0.0 and not bound.mimicked:
        travels = {}
        if clearance > start_travel(judge, np.array(start), np.array(end), bound, travels):
            return None, None
    return _judge(robot, joints, allowed, start, pairs, hand, judge), travels


def _checked_path(
    robot: RobotHandle,
    joints: tuple[str, ...],
    allowed: Collection[str],
    start: list[float],
    end: list[float],
    settings: MotionSettings,
    what: str,
    pairs: Collection[LinkPair] = (),
    hand: HandContact | None = None,
) -> JointPath:
    bound = TravelBound.of(robot, joints)
    desc = robot.description
    limits = joint_limits(desc, joints)
    box = ([lim.lower for lim in limits], [lim.upper for lim in limits])
    own = SelfPathCheck.of(robot, joints)
    _goal_apart(own, end, what)
    checker, travels = _straight_checker(robot, joints, allowed, start, pairs, end, bound, hand)
    try:
        if checker is None:  # nothing of the world near: free at once
            straight = JointPath(joints, (tuple(start), tuple(end)), "straight", 1)
        else:
            with posed(checker):  # the goal and the walk in one block: put back once
                straight = plan_joint_path(
                    checker, start, end, bound, box, plan=False, what=what,
                    explain=not settings.plan, start_free=True, start_travels=travels,
                )  # fmt: skip
                # planning explains a failure from its snapshot; the start's contacts allowed
        blocked = own.first_collision(straight.waypoints)
        if blocked is None:
            return straight
        if not settings.plan:
            raise _self_blocked(what, "straight path", blocked)
    except ManipulationPathBlocked:
        if not settings.plan:
            raise
    if checker is None:  # free of the world, but into itself: plan round on coal
        checker = _scene(robot, joints, allowed, start, pairs, hand)
    # a way round is planned on coal's clearances
    scene = checker if isinstance(checker, CoalClearance) else CoalClearance(checker)
    height = ToolHeight.of(robot, joints)
    if height is not None:
        detour = detour_path(scene, start, end, bound, box, height)
        if detour is not None and own.first_collision(detour.waypoints) is None:
            return detour
    return _planned(robot, scene, own, start, end, bound, box, settings, what)


def _planned(
    robot: RobotHandle,
    scene: CoalClearance,
    own: SelfPathCheck,
    start: list[float],
    end: list[float],
    bound: TravelBound,
    box: tuple[list[float], list[float]],
    settings: MotionSettings,
    what: str,
) -> JointPath:
    """A path OMPL plans on a coal snapshot, simplified under the world's judge and
    confirmed on the world. The self walk judges the simplifier only once a plan without
    it ran the robot into itself (it costs as much as the world's walk); a snapshot with a
    margin is taken only when the world refuses a planned path."""
    world = robot.world
    links = set(world.link_names(robot.name))
    hand = scene.judge.hand  # the snapshot lets it touch what it acts on, at any depth
    start_links = {  # links touching at the start may touch anything in the snapshot
        link for link, other in scene.judge.allowed_pairs
        if link in links and not (hand is not None and hand.covers(link, other))
    }  # fmt: skip
    failures: list[ManipulationPathBlocked] = []
    for margin in SNAPSHOT_MARGINS:  # the snapshot's hulls and Bullet's can differ by mm
        snapshot = CollisionScene.of(  # the goal passed the finer check on the meshes
            robot, scene.joints, allowed_links=scene.judge.allowed_links | start_links,
            margin=margin, allow_at=[end], hand=hand,
        )  # fmt: skip
        for apart in (False, True):
            judge = _WorldJudge(scene, bound, own if apart else None)
            try:
                path = plan_joint_path(
                    snapshot, start, end, bound, box, seed=settings.seed,
                    budget=settings.budget, what=what, judge=judge,
                )  # fmt: skip
            except ManipulationPathBlocked as failure:  # a margin only makes planning harder
                failures.append(failure)
                raise failures[0] from None
            blocked = None
            try:
                _confirm(scene, path, bound, what, judge)
                blocked = own.first_collision(path.waypoints)
                if blocked is not None:
                    raise _self_blocked(what, "planned path", blocked)
                return path
            except ManipulationPathBlocked as failure:
                failures.append(failure)
            if blocked is None:
                break  # the world refused the path: plan on a snapshot with a margin
    raise failures[0]  # the plan without a margin says best what is in the way


class _WorldJudge:
    """Whether a segment (its end included) is free on the world and, given ``own``, keeps
    the robot's links apart: a simplified path is pulled tight round obstacles (where the snapshot's
    hulls and the world's differ) and round the robot itself. It remembers the segments
    it found free, so confirming the path checks them only once."""

    def __init__(self, scene: CoalClearance, bound: TravelBound, own: SelfPathCheck | None) -> None:
        self.scene, self.bound, self.own = scene, bound, own
        self.counter = CheckCounter()
        self.free: set[bytes] = set()

    def __call__(self, a: FloatArray, b: FloatArray) -> bool:
        checkpoint()  # simplifying asks for many segments: a stopped task ends it here
        key = np.asarray(a, dtype=float).tobytes() + np.asarray(b, dtype=float).tobytes()
        if key in self.free:
            return True
        if (
            segment_free(self.scene, a, b, self.bound, self.counter)
            and self.scene.is_free(b)
            and (self.own is None or self.own.first_collision([a.tolist(), b.tolist()]) is None)
        ):
            self.free.add(key)
            return True
        return False


def _confirm(
    scene: CoalClearance, path: JointPath, bound: TravelBound, what: str, judge: _WorldJudge
) -> None:
    """Check a planned path on the world itself: the snapshot and the world must agree
    (segments ``judge`` found free while the path was simplified are not walked again)."""
    counter = CheckCounter()
    points = [np.array(w) for w in path.waypoints]
    for k, (a, b) in enumerate(zip(points, points[1:], strict=False)):
        if judge(a, b):
            continue
        hit = first_collision(scene, a, b, bound, counter)
        where, pairs = hit if hit is not None else (1.0, [])
        raise ManipulationPathBlocked(
            f"{what}'s planned path collides in the world {where:.0%} along segment {k + 1} "
            f"of {len(points) - 1} ({_named(pairs)}), though the planning snapshot found it free",
            colliding_pairs=tuple(pairs),
            path_fraction=(k + where) / (len(points) - 1),
        )


def _goal_apart(own: SelfPathCheck, goal: list[float], what: str) -> None:
    """Fail before planning when the goal itself puts the robot's links into each other."""
    pairs = own.colliding(goal)
    if pairs:
        raise ManipulationPathBlocked(
            f"{what}'s goal configuration puts the robot into itself: {_named(pairs)}",
            colliding_pairs=tuple(pairs),
            path_fraction=1.0,
        )


def _self_blocked(
    what: str, which: str, blocked: tuple[float, list[tuple[str, str]]]
) -> ManipulationPathBlocked:
    where, pairs = blocked
    return ManipulationPathBlocked(
        f"{what}'s {which} runs the robot into itself {where:.0%} along ({_named(pairs)})",
        colliding_pairs=tuple(pairs),
        path_fraction=where,
    )


def _named(pairs: list[tuple[str, str]]) -> str:
    return ", ".join(f"{a} hits {b}" for a, b in pairs[:4]) or "touching within its clearance"


def plan_tool_line(
    robot: RobotHandle,
    arm: str,
    target_in_base: Pose,
    *,
    allowed_links: Collection[str] = (),
    settings: MotionSettings = MotionSettings(),
    hand: HandContact | None = None,
) -> ArmMotion:
    """The straight line of ``arm``'s tool to ``target_in_base`` (the robot's root link),
    as far as it can be followed: ``fraction`` says how far (1: all of it). ``hand`` may
    touch what it acts on within its bound (the trajectory stores it)."""
    world = robot.world
    desc = robot.description
    spec = desc.arms[arm]
    joints = tuple(spec.joints)
    current = world.joint_states(robot.name)
    start = [current[j] for j in joints]
    base = world.pose(robot.name)
    tool = base.inverse() * world.link_pose(robot.name, spec.tool_frame)
    hand = hand_at_start(world, robot.name, hand)
    scene = _scene(robot, joints, allowed_links, start, hand=hand)
    bound = TravelBound.of(robot, joints)
    line = cartesian_path(
        desc, arm, scene, current, tool, target_in_base, bound, random_seed=settings.seed
    )
    fraction = line.fraction
    if fraction >= 1.0:  # a line cut short is not followed: no need to walk it
        blocked = SelfPathCheck.of(robot, joints).first_collision(line.path.waypoints)
        if blocked is not None:  # not followed: the caller moves in joint space instead
            fraction = blocked[0] if blocked[0] < 1.0 else 0.0
    limits = joint_limits(desc, joints)
    radii = (  # its gentle corners, checked; a line not followed needs none
        blend_radii(scene, bound, line.path.waypoints) if fraction >= 1.0 else None
    )
    trajectory = time_parameterize(
        robot.name, joints, line.path.waypoints, limits, kind="cartesian", period=settings.period,
        corner_radii=radii,
    )  # fmt: skip
    return ArmMotion(line.path, _with_hand(trajectory, hand), fraction)

"""Going to a container and opening it, and later closing it again from where it was opened.

CRAM opens a drawer when the object is known to be inside it and closes it once the object
is delivered. The stand comes from :func:`handle_stands` (in front of the handle on the
side the KB's ``container_front/3`` names, the arm's shoulder in line with it); each stand
is tried in turn, bounded, and a stand where the robot would collide or the arm cannot
hold the handle all the way gives the next one. A legged robot for which no stand worked
tries them again crouched (:mod:`~robocram.plans.crouching`), and closes what it opened
crouched as deep, both down at the stand and up again before it drives on.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass

from robocram.execution.failures import (
    EnvironmentManipulationImpossible,
    NavigationLowLevelFailure,
    NavigationPathBlocked,
    NavigationPoseUnreachable,
    PlanFailure,
    TorsoLowLevelFailure,
)
from robocram.knowledge import robot_predicates as rp
from robocram.knowledge.scene_predicates import CONTAINER, CONTAINER_FRONT, CONTAINER_KIND
from robocram.knowledge.world_predicates import OBJECT_POSE
from robocram.logic import current_kb
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import look_ahead, move_torso, navigate, park_arms, park_neck
from robocram.plans.containers import Container, close_container, container, open_container
from robocram.plans.crouching import DEPTHS, can_crouch, crouch, crouched, stand_up
from robocram.plans.environment_links import environment_link_pose
from robocram.plans.errors import PlanSetupError
from robocram.plans.known_robot import current_robot
from robocram.plans.stands import HandleStand, handle_stands, map_pose, yaw_of
from robocram.tf import Pose

OPEN_RETRIES = 6  # stands tried before opening gives up
TURNED = 0.05  # [rad | m] a neck joint moved this much by looking ahead was turned away
NEAR = 0.05  # [m] a base this close to the opening stand after opening stood there
TORSO_MOVED = 0.02  # [m | rad] a torso this far from where it was when a part was opened moved
CLOSING_ASIDE = (0.2, -0.2)  # [m] along its front: last stands to close an open drawer from
OPEN_ENOUGH = 0.8  # of a part's opening: a failed opening that left it this far open opened it
# closing failures after which the next stand is tried: the arm could not take the handle,
# or the base cannot stand where it opened the part (a Boxy's wide base meets the drawer
# it pulled out, and backed off as it pulled)
ANOTHER_STAND_HELPS = (EnvironmentManipulationImpossible, NavigationLowLevelFailure)


@dataclass(frozen=True)
class OpenedContainer:
    """A container a plan opened, the stand and arm that opened it, where the base stood
    when it was open (a door's arc can take the base a metre along) and the torso's
    position then [m | rad] (None: no torso), and how deep [m] the robot crouched to open
    it (0: standing; it is closed as deep)."""

    container: Container
    stand: HandleStand
    reached: Pose | None = None
    torso: float | None = None
    crouch: float = 0.0


def is_container(environment: str, link: str) -> bool:
    """Whether the KB names ``link`` of ``environment`` a container."""
    return CONTAINER.holds(current_kb(), environment=environment, link=link)


def _handle_pose(part: Container) -> Pose:
    return environment_link_pose(part.environment, part.handle, "a handle")


def is_drawer(part: Container) -> bool:
    """Whether the KB names ``part`` a drawer (else a door)."""
    return CONTAINER_KIND.holds(
        current_kb(), environment=part.environment, link=part.link, kind="drawer"
    )


def front_in_map(part: Container) -> float | None:
    """The map yaw [rad] out of ``part``'s front, if the KB gives it.

    ``container_front/3`` is in the environment's frame, so the environment's own turn in
    the world is added; without the fact (or the pose) the caller falls back on the handle.
    """
    kb = current_kb()
    fact = CONTAINER_FRONT.first(kb, environment=part.environment, link=part.link)
    if fact is None:
        return None
    row = OBJECT_POSE.first(kb, object=part.environment)
    if row is None:
        return None
    return fact.front + yaw_of(row.pose)


def opening_stands(part: Container) -> Iterator[HandleStand]:
    """Stands in front of ``part``'s handle for the current robot, each arm in the KB's order."""
    robot = current_robot()
    handle = _handle_pose(part)
    drawer = is_drawer(part)
    return handle_stands(robot, robot.arms(), handle, part.opened, drawer, front_in_map(part))


def open_from_front(
    name: str, log: AttemptLog | None = None, retries: int = OPEN_RETRIES
) -> OpenedContainer:
    """Go in front of container ``name`` (link or handle) and open it fully. When no stand
    worked and the head was turned away (down at what the robot last looked at), it looks
    ahead and the stands are tried once more: a Stretch's lift, rising to the fridge's
    handle, met its head still turned down at a cutlery drawer; a Boxy's neck, still
    turned to where it last looked, put its camera into the fridge at every stand in
    front of it (:func:`_neck_in_the_way`). When that did not help either, the neck is
    parked (its parking configuration from the KB) and the stands are tried once more:
    a Boxy's neck, looking ahead from where clearing the table left it, still put its
    links into the fridge, the counter or the cutlery unit at every stand; parked, two
    stands were free.

    Raises:
        PlanFailure: the last failure, when no stand within ``retries`` worked.
    """
    log = log if log is not None else AttemptLog()
    part = container(name)
    try:
        return _open_standing(part, log, retries)
    except EnvironmentManipulationImpossible as failure:
        if not can_crouch():
            raise
        last: PlanFailure = failure
    for depth in DEPTHS:  # a legged robot's holds out of reach standing: crouched
        try:
            return _open_from_stands(part, log, retries, depth)
        except PlanFailure as failure:
            last = failure if not isinstance(failure, TorsoLowLevelFailure) else last
    raise last  # a crouch that could not even bend says less than the standing failure


def _open_standing(part: Container, log: AttemptLog, retries: int) -> OpenedContainer:
    """:func:`open_from_front` standing: its stands, then looking ahead, then the neck
    parked."""
    try:
        return _open_from_stands(part, log, retries)
    except (EnvironmentManipulationImpossible, NavigationPoseUnreachable) as failure:
        if not _neck_in_the_way(failure):
            raise
        last: PlanFailure = failure
    if _neck_turned(look_ahead):
        try:
            return _open_from_stands(part, log, retries)
        except (EnvironmentManipulationImpossible, NavigationPoseUnreachable) as failure:
            if not _neck_in_the_way(failure):
                raise
            last = failure
    if not _neck_turned(park_neck):
        raise last
    return _open_from_stands(part, log, retries)


def _neck_in_the_way(failure: PlanFailure) -> bool:
    """Whether looking ahead may help after ``failure``, the last stand's: an opening that
    failed, or a stand the base could not take with the neck among the robot's links that
    would collide there (at the stand: a way there blocked on the way is not judged)."""
    if not isinstance(failure, NavigationPoseUnreachable):
        return True
    if isinstance(failure, NavigationPathBlocked):
        return False
    neck = set(current_robot().neck_links())
    return any(link in neck for link in failure.robot_links or ())


def _open_from_stands(
    part: Container, log: AttemptLog, retries: int, depth: float = 0.0
) -> OpenedContainer:
    """Open ``part`` from the first of its stands (at most ``retries``) that works,
    crouched ``depth`` [m] at each (0: standing), standing up after."""
    last: PlanFailure | None = None
    for _, stand in zip(range(retries), opening_stands(part), strict=False):
        try:
            park_arms()
            navigate(stand.pose)
            if depth > 0.0:
                crouch(depth)
            open_container(part.link, arm=stand.arm)
            park_arms()
        except PlanFailure as failure:
            log.record("open", stand.pose, failure)
            last = _open_on_from_here(part, stand, log) if _moved(failure) else failure
            if last is not None and not _open_enough(part, last):
                stand_up(depth)
                continue
            with contextlib.suppress(PlanFailure):
                park_arms()
        else:
            log.record("open", stand.pose, None)
        stand_up(depth)
        log.opened.append(part.link)
        robot = current_robot()
        reached = map_pose(robot.base_frame())
        return OpenedContainer(part, stand, reached, robot.torso_position(), depth)
    if last is None:
        raise PlanSetupError(f"no stand to open {part.link!r} from (retries={retries})")
    raise last


def _moved(failure: PlanFailure) -> bool:
    """Whether a failed opening left the part moved from closed."""
    reached = getattr(failure, "reached", None)
    return isinstance(failure, EnvironmentManipulationImpossible) and bool(reached)


def _open_on_from_here(part: Container, stand: HandleStand, log: AttemptLog) -> PlanFailure | None:
    """Open ``part`` on from where the last roll left the robot and the part, arms parked
    first (the rolls went on with the arm out where they got); the failure, None if it
    opened."""
    try:
        park_arms()
        open_container(part.link, arm=stand.arm)
    except PlanFailure as failure:
        log.record("open", map_pose(current_robot().base_frame()), failure)
        return failure
    return None


def _open_enough(part: Container, failure: PlanFailure) -> bool:
    """Whether a failed opening left ``part`` open by :data:`OPEN_ENOUGH` of its opening:
    it is open, and it is used (and closed again) as it is. The door stays where the rolls
    left it (nothing sets it back), and the stands in front of its handle are in its arc
    now: Boxy's left the fridge's door at 1.18 of 1.40 rad, and no stand opened it further."""
    if not isinstance(failure, EnvironmentManipulationImpossible) or failure.reached is None:
        return False
    return abs(failure.reached) >= OPEN_ENOUGH * abs(part.opened) > 0.0


def _neck_turned(turn: Callable[[], bool]) -> bool:
    """Run ``turn`` (look ahead, park the neck); whether it turned the neck by more than
    :data:`TURNED` on some joint (it was turned away)."""
    robot = current_robot()
    row = rp.ROBOT_NECK_JOINTS.first(current_kb(), robot=robot.name)
    joints = tuple(row.joints) if row is not None else ()
    before = [robot.joint_position(joint) for joint in joints]
    if not joints or not turn():
        return False
    after = [robot.joint_position(joint) for joint in joints]
    return any(
        b is not None and c is not None and abs(b - c) > TURNED
        for b, c in zip(before, after, strict=True)
    )


def close_again(opened: OpenedContainer, log: AttemptLog | None = None) -> None:
    """Go back to where ``opened`` was opened from and close it with the same arm; if the
    arm cannot take the handle from there (a door opened wide swung it out of reach: an
    HSR's arm follows the fridge door's arc only with its base, a metre along), or the
    base cannot stand there now, from where the base stood when it was open, by the
    handle. When neither did and the torso has moved since the part was opened, the torso
    goes back to where it was then and both stands are tried again: the parked arms hang
    lower with the torso down, and a Boxy's left arm, lowered by fetching from the drawer,
    met the open drawer at the very stand it had parked at beside it. Last, a drawer is
    closed from stands facing its open handle, aside of it (:func:`_closed_from_its_front`).

    Raises:
        PlanFailure: the last failure, when no stand closed it (the stands it opened from
            failing, their failure).
    """
    log = log if log is not None else AttemptLog()
    stands = [opened.stand.pose]
    if opened.reached is not None and opened.reached.distance_to(opened.stand.pose) > NEAR:
        stands.append(opened.reached)
    try:
        try:
            _closed_torso_back(opened, stands, log)
        except EnvironmentManipulationImpossible:
            if not park_neck():
                raise
            _close_from_stands(opened, stands, log)
    except EnvironmentManipulationImpossible:
        if not is_drawer(opened.container) or not _closed_from_its_front(opened, log):
            raise


def _closed_from_its_front(opened: OpenedContainer, log: AttemptLog) -> bool:
    """Whether a stand facing the open drawer's handle, :data:`CLOSING_ASIDE` of it along
    the front, closed it (stands the base cannot take cost nothing).

    The B1 opens the bowl's drawer rolling back and aside as it pulls (0.67 m), and neither
    there nor where it started does its Z1 take the open handle again: its IK puts the base
    0.23 m aside, and the drive there sweeps the jaw's fixed half 5.1-6.2 mm into the handle
    (the bound 5 mm). From a stand 0.2 m aside, 0.4 m before the open handle, it pushes the
    drawer shut (docs/new_robot.md, zoo24).
    """
    robot = current_robot()
    part = opened.container
    handle = _handle_pose(part)
    front = front_in_map(part)
    out = front if front is not None else yaw_of(handle)
    along = (-math.sin(out), math.cos(out))
    x, y, z = handle.position
    for aside in CLOSING_ASIDE:
        beside = Pose((x + along[0] * aside, y + along[1] * aside, z), handle.orientation)
        for stand in handle_stands(robot, [opened.stand.arm], beside, 0.0, True, front):
            try:
                park_arms()
                navigate(stand.pose)
                with crouched(opened.crouch):
                    close_container(part.link, arm=stand.arm)
                    park_arms()
            except PlanFailure as failure:
                log.record("close", stand.pose, failure)
                continue
            log.record("close", stand.pose, None)
            return True
    return False


def _closed_torso_back(opened: OpenedContainer, stands: list[Pose], log: AttemptLog) -> None:
    """Close ``opened`` from ``stands``; where that failed and the torso has moved since the
    part was opened, again with the torso back (:func:`close_again`). Last, where the arm
    could not hold the handle from any stand, :func:`close_again` parks the neck and tries
    the stands once more: the drafted Stretch, its head still turned down at the table's
    milk (pan -1.74, tilt -0.64 rad), closed the fridge it had opened from the same stand
    with the head parked only (household 0's clearing)."""
    try:
        _close_from_stands(opened, stands, log)
        return
    except ANOTHER_STAND_HELPS:
        before = current_robot().torso_position()
        if not _torso_back(opened):
            raise
    _close_from_stands(opened, stands, log)
    if before is not None:  # as the plan had it: what it does next is planned for that
        with contextlib.suppress(PlanFailure):
            move_torso(before)


def _close_from_stands(opened: OpenedContainer, stands: list[Pose], log: AttemptLog) -> None:
    """Close ``opened`` from the first of ``stands`` that works; the last failure raised."""
    for k, stand in enumerate(stands):
        try:
            park_arms()
            navigate(stand)
            with crouched(opened.crouch):
                close_container(opened.container.link, arm=opened.stand.arm)
                park_arms()
        except PlanFailure as failure:
            log.record("close", stand, failure)
            if k == len(stands) - 1 or not isinstance(failure, ANOTHER_STAND_HELPS):
                raise
            continue
        log.record("close", stand, None)
        return


def _torso_back(opened: OpenedContainer) -> bool:
    """Move the torso back to where it was when ``opened`` was opened, if it moved by more
    than :data:`TORSO_MOVED` since; whether it moved back."""
    now = current_robot().torso_position()
    if opened.torso is None or now is None or abs(now - opened.torso) <= TORSO_MOVED:
        return False
    try:
        move_torso(opened.torso)
    except PlanFailure:
        return False
    return True

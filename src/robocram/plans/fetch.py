"""Fetching: stand where the object is reachable, look, detect it again, pick it up.

As CRAM's fetch plan does, each try takes the next solution of a ``reachable_for``
location designator, so a stand whose grasp fails gives way to another one; the tries are
bounded (``stand_retries``; a stand where the robot would collide is skipped without
counting, at most ``MAX_BLOCKED`` of them). An object in a container the search opened is
tried first from in front of the container, arm by arm. When all fail, :class:`FetchExhausted` (an
``ObjectUnfetchable``) carries every cause in order.
"""

from __future__ import annotations

import contextlib
import itertools
import math
from collections.abc import Callable, Iterable, Iterator
from typing import Any

from robocram.designators import ObjectDesignator, a, an
from robocram.execution.failures import (
    ManipulationPoseUnreachable,
    NavigationPoseUnreachable,
    PerceptionObjectNotFound,
    PlanFailure,
    PtuGoalNotReached,
    PtuGoalUnreachable,
    failure_line,
)
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import detect, look_lowering, navigate, park_arms
from robocram.plans.container_access import OpenedContainer, is_drawer
from robocram.plans.crouching import crouched_at_stand
from robocram.plans.culprits import blamed, culprit_clause
from robocram.plans.detect_past_hand import detect_past_hand
from robocram.plans.drawer_side_stands import side_stands
from robocram.plans.errors import FetchExhausted, PlanArgumentError
from robocram.plans.flank_stands import flank_stands
from robocram.plans.grasp_stands import grasp_point_stands
from robocram.plans.known_robot import KnownRobot, current_robot
from robocram.plans.location_poses import location_poses, next_pose
from robocram.plans.out_of_view_reach import near_stands, out_of_view
from robocram.plans.peering import look_again
from robocram.plans.pick_object import Held, closed_into_surface, pick_up_object
from robocram.plans.place_looks import detected_round
from robocram.plans.stands import (
    REACH_DISTANCES,
    front_stands,
    map_pose,
    planar_pose,
    yaw_of,
)
from robocram.plans.torso_up import navigate_torso_up, torso_in_the_way
from robocram.tf import Pose, PoseStamped, transform_pose

STAND_RETRIES = 3  # stands where picking up is tried before fetching gives up
MAX_BLOCKED = 8  # stands where the robot would collide, skipped without a try
STILL_THERE = 0.01  # [m] a hidden thing this near where it was seen is taken from there
STEPPED_IN = 0.05  # [m] nearer the object than the opening stand: the robot peered in
FACING_TURNS = (0.0, math.pi / 2, -math.pi / 2, math.pi)  # [rad] from the robot's bearing
FACING_DISTANCES = (0.75, 0.85)  # [m] base to object, where no reach costmap cell is left


def perceived(object: ObjectDesignator | str) -> ObjectDesignator:  # noqa: A002 - CRAM's key
    """``object`` if perception already filled it in, else what detecting it now gives."""
    if isinstance(object, ObjectDesignator) and object.get("pose") is not None:
        return object
    return detect(object)


def _pick_from(
    stand: Pose,
    seen: ObjectDesignator,
    where: PoseStamped,
    arm: str | None,
    grasp: str | None,
    out_of: tuple[str, str] | None = None,
    in_container: bool = False,
    torso_up: bool = False,
    unseen: bool = False,
    raised: bool = False,
    over: bool = False,
    depth: float = 0.0,
) -> Held:
    """Drive to ``stand``, look at the object (``where``, map), detect it again, pick it
    up (lifting it out of ``out_of``, the opened drawer it lies in, if any). A thing seen
    ``in_container`` (one opened for it) that this stand does not show is taken where it
    was seen, if it is still there: :func:`fetch` asks that only after every stand failed
    (a PR2 that took a bowl blind from a drawer of PyCRAM's apartment held it where no
    stand could put it down; from a later stand that saw it, it delivers). With
    ``torso_up`` a stand refused for the lowered torso is driven to with it raised. With
    ``unseen``, a thing whose look stopped at the tilt limit with it outside the view is
    taken where it was seen, if it is still there, and every pick tries nearer pre-grasps
    after the usual (``plans/out_of_view_reach.py``). With ``raised``, a grasp whose closed
    fingers lay in the surface under the thing is tried again higher (``pick_object``).
    With ``over``, a look that stopped at the tilt limit above a thing in an opened drawer
    (``out_of``) takes it where it was seen as ``unseen`` does, in the view's lower edge
    or under it (:func:`_looked_over`). With ``depth`` > 0 a legged robot crouches that
    deep [m] once there, and stands up again after (``plans/crouching.py``)."""
    park_arms()
    (navigate_torso_up if torso_up else navigate)(stand)
    with crouched_at_stand(depth):
        return _look_and_pick(seen, where, arm, grasp, out_of, in_container, unseen, raised, over)


def _look_and_pick(
    seen: ObjectDesignator,
    where: PoseStamped,
    arm: str | None,
    grasp: str | None,
    out_of: tuple[str, str] | None,
    in_container: bool,
    unseen: bool,
    raised: bool,
    over: bool,
) -> Held:
    """:func:`_pick_from` once at the stand: look, detect again, pick up."""
    wanted = an.object(type=seen.get("type"), name=seen.get("name"))
    try:
        look_lowering(where)
    except PtuGoalNotReached as failure:
        as_seen = (unseen and out_of_view(failure)) or (over and _looked_over(failure, out_of))
        if not (as_seen and _still_there(seen, where)):
            raise
        blind = an.object(type=seen.get("type"), name=seen.get("name"), pose=where)
        return pick_up_object(
            blind, arm=arm, grasp=grasp, out_of=out_of, nearer=True, raised=raised
        )
    except PtuGoalUnreachable as failure:  # a wrist camera not turned there: round it
        robot_frame = current_robot().base_frame()
        again = detected_round(wanted, where, robot_frame, failure, detect_past_hand)
        return pick_up_object(
            again, arm=arm, grasp=grasp, out_of=out_of, nearer=unseen, raised=raised
        )
    try:
        again = detect_past_hand(wanted)
    except PerceptionObjectNotFound as hidden:  # hidden at this height: another may show it
        found = look_again(where, lambda: _detected(wanted))
        if found is None and not (in_container and _still_there(seen, where)):
            raise hidden
        again = found or an.object(type=seen.get("type"), name=seen.get("name"), pose=where)
    return pick_up_object(again, arm=arm, grasp=grasp, out_of=out_of, nearer=unseen, raised=raised)


def _still_there(seen: ObjectDesignator, where: PoseStamped) -> bool:
    """Whether the named object ``seen`` lies where it was seen (``where``, map) to within
    :data:`STILL_THERE`: a thing seen from farther back, which the stand that reaches it
    sees no more (a Boxy's camera, high over a fridge's shelf, sees the milk under it from
    0.8 m back only), is taken where it was seen."""
    name = seen.get("name")
    if name is None:
        return False
    return map_pose(str(name)).distance_to(where.pose) <= STILL_THERE


def _out_of_reach(causes: list[Exception]) -> bool:
    """Whether every try that came to the object failed for its reach (the stands refused
    to the base, and the designator's end, aside): the stands stood too far from it."""
    tried = [c for c in causes if isinstance(c, PlanFailure)]
    tried = [c for c in tried if not isinstance(c, NavigationPoseUnreachable)]
    return bool(tried) and all(isinstance(c, ManipulationPoseUnreachable) for c in tried)


def _looked_over(failure: PlanFailure, out_of: tuple[str, str] | None) -> bool:
    """Whether ``failure`` is a look that stopped at the head's tilt limit above an object
    in an opened drawer (``out_of``), in the view's lower edge or under it: Armar6's head tilts
    0.8 rad down at most, and from 0.55 m in front of the bowl's open drawer, the stand
    its arms lift the bowl out from, it needs 1.09 (the bowl in the view's lower edge, not
    within the half that counts as seen); from 0.65 m, where it looks, no lift clears the
    drawer. Such a stand is tried last, the thing taken where it was seen."""
    return out_of is not None and isinstance(failure, PtuGoalNotReached) and failure.below_tilt


def _detected(wanted: ObjectDesignator) -> ObjectDesignator | None:
    """``wanted`` as the robot sees it now; None if it does not."""
    try:
        return detect(wanted)
    except PerceptionObjectNotFound:
        return None


def _drawer_of(opened: OpenedContainer | None) -> tuple[str, str] | None:
    """The opened drawer (environment, link) a pick must lift the object out of; a door's
    shelf is left sideways, so None for it (and for no container)."""
    if opened is None or not is_drawer(opened.container):
        return None
    return opened.container.environment, opened.container.link


def square_up(robot: KnownRobot) -> None:
    """Turn the base in place to the nearest quarter turn (a costmaps workaround).

    The occupancy layer measures the base's footprint from world-aligned bounds, which
    grow when the base is turned (docs/transport.md, known limits): squared up, the
    ``reachable_for`` costmap keeps the cells near a counter. A turn that would collide is
    skipped; the stand is then resolved from where the robot stands.
    """
    here = map_pose(robot.base_frame())
    yaw = yaw_of(here)
    squared = round(yaw / (math.pi / 2)) * (math.pi / 2)
    if abs(squared - yaw) < 1e-3:
        return
    with contextlib.suppress(NavigationPoseUnreachable):
        navigate(planar_pose(here.position[0], here.position[1], squared))


def _stands(
    seen: ObjectDesignator,
    where: PoseStamped,
    arm: str | None,
    opened: OpenedContainer | None,
    causes: list[Exception],
) -> Iterator[tuple[Pose, str | None]]:
    """Stands (map) and the arm to use there: in front of an opened container first (the
    costmap keeps a whole base radius off its open drawer), then ``reachable_for``'s."""
    robot = current_robot()
    if opened is not None:
        here = map_pose(robot.base_frame())
        if _stepped_in(here, opened.stand.pose, where.pose):
            yield here, arm  # where it peered in from: it sees the object there
        arms = [arm] if arm is not None else robot.arms()
        # the container's front faces the arm that opened it: a sideways arm's (the
        # Stretch's) base stood turned from it by its working direction
        out = yaw_of(opened.stand.pose) + robot.working_yaw(opened.stand.arm) + math.pi
        for stand in front_stands(robot, arms, where.pose, out, REACH_DISTANCES):
            yield stand.pose, stand.arm
    square_up(robot)
    keys: dict[str, Any] = {"arm": arm} if arm is not None else {}
    poses = location_poses(a.location(reachable_for=robot.name, object=seen.get("name"), **keys))
    found = False
    while (pose := next_pose(poses, causes)) is not None:
        found = True
        yield pose, arm
    if not found:
        yield from _facing_stands(robot, where, arm)


def _facing_stands(
    robot: KnownRobot, where: PoseStamped, arm: str | None
) -> Iterator[tuple[Pose, str | None]]:
    """Stands facing the object from the robot's side of it, then from either side and
    the far side, :data:`FACING_DISTANCES` away, arm by arm: where the reach costmap has
    no cell (an HSR's map reaches 0.65 m at a table's height, and its base stands no
    nearer than that to the milk in the table's middle, which its arm held out to the
    side put there from 0.8 m)."""
    here = map_pose(robot.base_frame()).position
    x, y, _ = where.pose.position
    towards = math.atan2(here[1] - y, here[0] - x)
    arms = [arm] if arm is not None else robot.arms()
    for turn in FACING_TURNS:
        for stand in front_stands(robot, arms, where.pose, towards + turn, FACING_DISTANCES):
            yield stand.pose, stand.arm


def _stepped_in(here: Pose, stand: Pose, target: Pose) -> bool:
    """Whether the base at ``here`` stands nearer ``target`` than ``stand`` (where the
    container was opened from) by more than :data:`STEPPED_IN`: a robot that stepped
    closer to see into it (``plans/peering.py``)."""
    x, y, _ = target.position
    near = math.hypot(here.position[0] - x, here.position[1] - y)
    return near < math.hypot(stand.position[0] - x, stand.position[1] - y) - STEPPED_IN


def exhausted_message(name: str, tries: int, causes: list[Exception]) -> str:
    """Why fetching ``name`` gave up, counted as it happened, with the last cause's line.

    A try is a stand where picking up was tried; when there was none, the message says that
    no stand was found, or that every stand found was blocked, rather than "0 tries".
    Objects the causes blame (a location's ``blocked_by``, ``occluded_by``) come first.
    """
    blocked = sum(isinstance(c, NavigationPoseUnreachable) for c in causes)
    culprits = culprit_clause(blamed(causes, "occluded_by"), blamed(causes, "blocked_by"))
    if tries:
        text = f"could not fetch {name} in {tries} tr{'y' if tries == 1 else 'ies'}{culprits}"
    elif blocked:
        text = (
            f"could not fetch {name}{culprits}: the robot would collide at each of {blocked} stands"
        )
    else:
        text = f"no stand found for {name}{culprits}"
    if not causes:
        return text
    last = causes[-1]
    joint = "; the last: " if tries or blocked > 1 else ": "
    return text + joint + failure_line(type(last).__name__, str(last))


def _untried(stands: Iterator[tuple[Pose, str | None]]) -> Iterator[tuple[Pose, str | None]]:
    """The stands the tries did not come to, tried last from an opened container: a row
    in front of the drawer, from which the lift out of it is beyond reach, used the tries
    up (Boxy's left hand at its cups: a stand on the cups' other side took them)."""
    return stands


def _first_held(
    stands: Iterable[tuple[Pose, str | None]],
    pick: Callable[[Pose, str | None], Held],
    causes: list[Exception],
    log: AttemptLog,
    limit: int,
) -> Held | None:
    """The thing held from the first of ``stands`` that ``pick`` works from (None: none
    did); each failure goes to ``causes``; after ``limit`` stands that failed once there,
    no more (a stand refused to the base costs no try)."""
    tries = 0
    for pose, use_arm in stands:
        if tries >= limit:
            break
        try:
            held = pick(pose, use_arm)
        except NavigationPoseUnreachable as failure:  # refused: the next stand, no try
            causes.append(failure)
            log.record("fetch", pose, failure)
            continue
        except PlanFailure as failure:
            causes.append(failure)
            log.record("fetch", pose, failure)
            tries += 1
            continue
        log.record("fetch", pose, None)
        return held
    return None


def _suction(robot: KnownRobot, arm: str | None) -> bool:
    """Whether ``arm`` (or, for None, any arm) is a suction hand: only a suction hand's level
    side touch gains from a flank stand; fingered hands have their own side grasps from
    the usual stands."""
    return any(robot.is_suction(a) for a in ([arm] if arm is not None else robot.arms()))


def fetch(
    object: ObjectDesignator | str,  # noqa: A002 - CRAM's key
    arm: str | None = None,
    grasp: str | None = None,
    stand_retries: int = STAND_RETRIES,
    log: AttemptLog | None = None,
    opened: OpenedContainer | None = None,
    depth: float = 0.0,
) -> Held:
    """Pick up the (perceived) object from a stand that reaches it; what the hand holds.

    ``opened`` is the container the object lies in, if a search opened one; ``depth`` [m]:
    a legged robot crouches that deep at each stand after the drive (0: it stands).

    Raises:
        FetchExhausted: no stand within ``stand_retries`` led to the object being held.
    """
    if stand_retries < 1:
        raise PlanArgumentError(f"stand_retries must be at least 1, got {stand_retries}")
    log = log if log is not None else AttemptLog()
    seen = perceived(object)
    where = transform_pose(seen.get("pose"), "map")  # before the base moves: its frame moves
    causes: list[Exception] = []
    tries = 0
    stands = _stands(seen, where, arm, opened, causes)
    out_of = _drawer_of(opened)
    hidden: list[tuple[Pose, str | None]] = []  # stands that did not show it in its container
    lowered: list[tuple[Pose, str | None]] = []  # stands refused for the lowered torso only
    tried: list[tuple[Pose, str | None]] = []  # stands whose pick failed
    below: list[tuple[Pose, str | None]] = []  # stands whose look stopped above it, in a drawer
    robot = current_robot()
    for pose, use_arm in itertools.islice(stands, stand_retries + MAX_BLOCKED):
        try:
            held = _pick_from(pose, seen, where, use_arm, grasp, out_of, depth=depth)
        except NavigationPoseUnreachable as failure:  # in the way: the next stand, no try
            causes.append(failure)
            log.record("fetch", pose, failure)
            if torso_in_the_way(robot, failure):
                lowered.append((pose, use_arm))
            continue
        except PlanFailure as failure:
            causes.append(failure)
            log.record("fetch", pose, failure)
            if isinstance(failure, PerceptionObjectNotFound) and opened is not None:
                hidden.append((pose, use_arm))
            if _looked_over(failure, out_of):
                below.append((pose, use_arm))
            tried.append((pose, use_arm))
            tries += 1
            if tries >= stand_retries:
                break
            continue
        log.record("fetch", pose, None)
        return held

    def picking(**keys: bool) -> Callable[[Pose, str | None], Held]:
        return lambda pose, use_arm: _pick_from(
            pose, seen, where, use_arm, grasp, out_of, depth=depth, **keys
        )

    for stands_left, pick, limit in (  # then the torso raised where it alone was in the
        (lowered, picking(torso_up=True), stand_retries),  # way; last: where it was seen,
        (hidden, picking(in_container=True), len(hidden)),  # from a stand that did not see it
    ):
        found = _first_held(stands_left, pick, causes, log, limit)
        if found is not None:
            return found
    if opened is not None:  # last: in line with a grasp's point aside of the middle
        arms = [arm] if arm is not None else robot.arms()
        aside = grasp_point_stands(robot, seen, where, arms, opened)
        found = _first_held(aside, picking(torso_up=True), causes, log, stand_retries)
        if found is not None:
            return found
        found = _first_held(_untried(stands), picking(), causes, log, stand_retries)
        if found is not None:
            return found
        if out_of is not None:  # last of all: beside the drawer, over its low side wall
            beside = side_stands(robot, where, arms, opened)
            found = _first_held(beside, picking(in_container=True), causes, log, stand_retries)
            if found is not None:
                return found
    if tries and _out_of_reach(causes):  # last: nearer, where the camera may not see it
        near = near_stands(robot, where, arm)
        found = _first_held(near, picking(unseen=True), causes, log, stand_retries)
        if found is not None:
            return found
    if any(closed_into_surface(c) for c in causes):  # last: the stands again, grasping higher
        found = _first_held(tried, picking(raised=True), causes, log, stand_retries)
        if found is not None:
            return found
    if tries and opened is None and _suction(robot, arm):  # last: the base turned a
        flank = flank_stands(robot, where, arm)  # quarter, its flank nearer (side touches)
        found = _first_held(flank, picking(), causes, log, stand_retries)
        if found is not None:
            return found
    if below:  # last: a drawer's stands whose look stopped above it, taken where seen
        found = _first_held(below, picking(unseen=True, over=True), causes, log, len(below))
        if found is not None:
            return found
    raise FetchExhausted(
        exhausted_message(str(seen.get("name")), tries, causes),
        object_designator=seen,
        causes=tuple(causes),
        attempts=tries,
        blocked_by=blamed(causes, "blocked_by") or None,
        occluded_by=blamed(causes, "occluded_by") or None,
    )

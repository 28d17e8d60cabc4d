"""Pick up any detected object: open, pre-grasp, grasp, grip, lift, with any robot.

The grasps come from the knowledge base (``object_grasp/7``, installed by the projection
from the grasp model, docs/grasping.md), best first for each arm; arms are tried nearest
first. A try that fails (the pose is out of reach, the grip closes on nothing) moves on to
the next grasp, then the next arm; when all fail, :class:`PickUpFailed` carries every
cause.

An object in an opened drawer is lifted out of it (``out_of``): the lift rises until its
bottom clears the drawer's top (``lift_clearance/4``), and IK must reach that lift from
where the robot stands (``pose_reachable/3``) before the hand moves; a grasp whose lift
is out of reach is not tried. Boxy once gripped the bowl from a stand where its arm
could not raise it over the drawer's front panel, and no delivery could start.
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from robocram.designators import ObjectDesignator, a
from robocram.execution import perform
from robocram.execution.failures import (
    GripperLowLevelFailure,
    GripperMetOneSide,
    GripperPathBlocked,
    ManipulationLowLevelFailure,
    ManipulationPoseUnreachable,
    NavigationLowLevelFailure,
    PlanFailure,
)
from robocram.knowledge.grasp_predicates import OBJECT_GRASP, OBJECT_UNGRASPABLE, ObjectGrasp
from robocram.knowledge.reasoning_predicates import (
    ARM_POSE_REACHABLE,
    LIFT_CLEARANCE,
    LINE_STAND,
)
from robocram.knowledge.robot_predicates import GRIPPER_JOINT
from robocram.logic import Term, UnknownPredicateError, current_kb
from robocram.plans.basic_actions import look_ahead, neck_in_the_way, park_arms
from robocram.plans.empty_hand_up import navigate_empty_hand_up
from robocram.plans.errors import PlanSetupError
from robocram.plans.grasp_failures import ObjectUngraspable, PickUpFailed, PickUpUnreachable
from robocram.plans.known_robot import KnownRobot, current_robot
from robocram.plans.nearer_pre_grasp import (
    NEARER_LIFT_SHARE,
    NEARER_SHARE,
    NEAREST_SHARE,
    nearer_pre_grasp,
    towards,
)
from robocram.plans.still_where_seen import still_where_seen
from robocram.tf import Pose, PoseStamped, TfError, transform_pose

CENTRINGS = 2  # a grip meeting the object on one side moves the hand this often at most
GRASPING = {"collision_mode": "allow_hand"}  # the fingers may touch what they close on:
# a motion names it too (``touching``), and the hand may touch nothing else, 5 mm at most
PART_WAY = 1 / 3  # of the open master finger joint's value: a rim grasp tried again with
# the hand opened so far only (the drafted Stretch's fingers, fully open, span 12 cm: at a
# bowl's wall the outer one met the next bowl or the drawer's front; a third suffices).
# Taken from zero, where the fingers of the Stretch and the PR2 meet: a gripper closed
# above zero gets a value nearer open or out of range, and its retry only fails again
HALF_WAY = 1 / 2  # of the same value: any other grasp a finger was caught at tried again
# so (the fingers go round the whole object, so a third may be narrower than it: the
# drafted Stretch's fingers close on a cup at 0.22 of their 0.60 rad; fully open, one met
# the counter top over the drawer or slid outside the drawer's side wall)
NARROW = PART_WAY  # of the same value: last, any grasp in a drawer a finger was caught
# at, opened so (the drafted Stretch's spoon in an east drawer, the knife 8.2 cm beside it:
# fully open, 21 cm between the fingertips, the right one came down on the knife; half open
# it still lay 1.2 cm over the knife's edge; a third leaves 7.6 cm for the 3.5 cm spoon and
# clears the knife by 5 mm)
TRIES = (ManipulationLowLevelFailure, GripperLowLevelFailure, NavigationLowLevelFailure)
DRAW_BACK = 0.2  # [m] past the pre-grasp a hand that took a thing from a line stand draws it
# back (the fridge's milk, gripped 21 cm behind the fridge's front, 10 cm past the pre-grasp:
# a drive with it still in the shelf turned it into the shelf)
BACK_OUT_SHARE = 0.5  # of the way from the grasp to the pre-grasp, where a hand whose
# whole way out failed goes first
RAISES = (0.005, 0.01)  # [m] a grasp whose closed fingers' goal lay in the surface under the
# thing, tried again this much higher (the drafted Stretch's curved fingertips, closing on a
# spoon flat on the table at 0.087 rad, dipped into the table's top from every stand)
LOWER_LIFTS = (0.5, 0.25)  # of a lift's rise over the grasp, tried in turn from a line stand
# where the whole rise is out of the arm's reach (the drafted Stretch's lift at the fridge's
# milk: the tool rises 5.7 cm at most there, the usual lift is 10 cm)


@dataclass(frozen=True)
class Held:
    """An object held by an arm: the grasp used and the tool poses (``map``) it took."""

    arm: str
    grasp: str
    object_name: str
    tool_frame: str
    grasp_pose: PoseStamped
    lifted: PoseStamped
    object_in_tool: Pose  # the object's pose in the tool frame while held


def object_spec(obj: ObjectDesignator | str) -> tuple[str, Any, Pose | None]:
    """The object's name, how the grasp predicates name it, and its pose in ``map``.

    A perceived designator with a type and a pose is ``object(Name, Type, Pose)``, so the
    grasps come from its type where no world knows it; a name is looked up in the world.
    """
    name = object_name(obj)
    if isinstance(obj, ObjectDesignator) and obj.get("pose") is not None and obj.get("type"):
        pose = transform_pose(obj.get("pose"), "map")
        return name, Term("object", (name, str(obj.get("type")), pose)), pose.pose
    try:
        return name, name, transform_pose(PoseStamped(name), "map").pose
    except TfError:
        return name, name, None


def object_name(obj: ObjectDesignator | str) -> str:
    """The world name of a perceived object designator (or a name itself)."""
    if isinstance(obj, str):
        return obj
    name = obj.get("name")
    if name is None:
        raise PlanSetupError(
            f"{obj.description} has no name: detect it first (a perceived object designator)"
        )
    return str(name)


def arms_nearest_first(robot: KnownRobot, target: Pose | None, arm: str | None) -> list[str]:
    """``[arm]``, or the robot's arms with a gripper, their tool frames nearest first."""
    if arm is not None:
        return [arm]
    arms = robot.grasping_arms()
    if not arms:
        raise PlanSetupError(f"{robot.name} has no arm with a gripper (grasping_arm/2)")
    if target is None:
        return arms

    def distance(choice: str) -> float:
        tool = transform_pose(PoseStamped(robot.tool_frame(choice)), "map").pose
        return tool.distance_to(target)

    return sorted(arms, key=distance)


def grasp_choices(
    robot: KnownRobot, spec: object, arm: str, grasp: str | None
) -> list[ObjectGrasp]:
    """The KB's grasps of ``name`` by ``arm`` (only ``grasp`` if given), best first.

    Raises:
        ObjectUngraspable: the hand is too narrow for every grasp of the object.
    """
    kb = current_kb()
    name = str(spec.args[0]) if isinstance(spec, Term) else str(spec)
    named = {} if grasp is None else {"grasp": grasp}
    found = list(OBJECT_GRASP.answers(kb, object=spec, robot=robot.name, arm=arm, **named))
    if not found:
        refusal = OBJECT_UNGRASPABLE.first(kb, object=spec, robot=robot.name, arm=arm)
        if refusal is not None:
            raise ObjectUngraspable(
                f"no grasp of {name!r} fits the {arm} hand of {robot.name}: it opens "
                f"{refusal.hand_width:.3f} m, the narrowest grasp needs "
                f"{refusal.needed_width:.3f} m",
                object_name=name,
                arm=arm,
                hand_width=refusal.hand_width,
                needed_width=refusal.needed_width,
            )
    return found


def _move(arm: str, pose: PoseStamped, **mode: str) -> None:
    perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=pose), **mode))


def _lifted_out(
    robot: KnownRobot, name: str, arm: str, choice: ObjectGrasp, out_of: tuple[str, str]
) -> ObjectGrasp:
    """``choice`` with its lift raised until ``name`` clears the top of ``out_of``
    (environment, link), checked by IK from where the robot stands. A KB without the
    reach predicates (no world to ask) keeps the lift as it is.

    Raises:
        ManipulationPoseUnreachable: ``arm`` cannot reach the raised lift from here.
    """
    kb = current_kb()
    environment, link = out_of
    try:
        answer = LIFT_CLEARANCE.first(kb, object=name, body=environment, link=link)
    except UnknownPredicateError:
        return choice
    rise = 0.0 if answer is None else answer.rise
    x, y, z = choice.lift.position
    lift = replace(choice.lift, position=(x, y, max(z, choice.grasp_pose.position[2] + rise)))
    if not ARM_POSE_REACHABLE.holds(kb, robot=robot.name, arm=arm, pose=lift):
        raise ManipulationPoseUnreachable(
            f"{robot.name}'s {arm} arm cannot lift {name!r} out of {link!r} from here: the tool "
            f"does not reach {lift.position[2]:.3f} m over the grasp; stand elsewhere",
            target=lift,
        )
    return replace(choice, lift=lift)


@dataclass
class _WayOut:
    """The pre-grasp a hand came in from, while a failed try left it at its grasp (in a
    drawer, round the object); ``arm`` None while every hand is out at a pre-grasp."""

    arm: str | None = None
    pre_grasp: PoseStamped | None = None
    opened: bool = False  # the last try's hand opened where it stood (before its pre-grasp)


def _try_grasp(
    robot: KnownRobot,
    name: str,
    arm: str,
    choice: ObjectGrasp,
    object_in_map: Pose | None,
    lift: bool = True,
    way_out: _WayOut | None = None,
    part_way: float | None = None,
    near: bool = False,
    lower_lifts: bool = False,
) -> Held:
    still_where_seen(name, object_in_map)
    way_out = way_out or _WayOut()
    way_out.opened = False
    mode = {**GRASPING, "touching": name} if near else {}
    _opened_at(arm, choice.pre_grasp, part_way, way_out, **mode)
    way_out.arm = None
    _move(arm, choice.grasp_pose, **GRASPING, touching=name)
    way_out.arm, way_out.pre_grasp = arm, choice.pre_grasp
    choice = _gripped(arm, name, choice)
    if lift:
        lifted = _lifted(arm, choice.lift, name, choice.grasp_pose if lower_lifts else None)
        choice = replace(choice, lift=lifted)
    frame = robot.tool_frame(arm)
    if object_in_map is None:
        object_in_map = transform_pose(PoseStamped(name), "map").pose
    held = choice.grasp_pose.pose.inverse() * object_in_map  # as gripped: the grasp keeps it
    raised = choice.lift if lift else choice.grasp_pose
    return Held(arm, choice.grasp, name, frame, choice.grasp_pose, raised, held)


def _opened_at(
    arm: str,
    pre_grasp: PoseStamped,
    part_way: float | None = None,
    way_out: _WayOut | None = None,
    **mode: str,
) -> None:
    """Open the gripper and move to the pre-grasp (in the motion's ``mode``: a pre-grasp
    near the grasp may touch the object); where the fingers opening would meet the
    robot's body (the Z1 on a B1 looked with its jaw beside a leg), move there first and
    open there. ``part_way``: opened fully, then closed to that fraction of it. Once the
    hand is open, ``way_out.opened`` says so."""
    try:
        perform(a.motion(type="opening", gripper=arm))
        if way_out is not None:
            way_out.opened = True
        if part_way is not None:
            _close_part_way(arm, part_way)
    except GripperPathBlocked as blocked:
        if not _fingers_meet_body(arm, blocked):
            raise
        _to_pre_grasp(arm, pre_grasp, **mode)
        perform(a.motion(type="opening", gripper=arm))
        if way_out is not None:
            way_out.opened = True
        return
    _to_pre_grasp(arm, pre_grasp, **mode)


def _close_part_way(arm: str, fraction: float) -> None:
    """Close ``arm``'s open gripper to ``fraction`` of its open master joint value."""
    robot = current_robot()
    row = GRIPPER_JOINT.first(current_kb(), robot=robot.name, arm=arm)
    opened = robot.joint_position(row.joint) if row is not None else None
    if opened is not None:
        angle = opened * fraction
        perform(a.motion(type="moving-gripper-joint", gripper=arm, joint_angle=angle))


def _finger_caught(robot: KnownRobot, arm: str, failure: Exception, opened: bool) -> bool:
    """Whether ``failure`` blames a finger of ``arm`` meeting something, which a hand opened
    part way may miss: IK solutions or a path refused for a finger and for no other link of
    the hand (a palm or wrist in the way stays there however far the fingers open), or a
    grip that met the object on one side only. Not where the hand did not open (``opened``
    false: the retry opens it fully first, where it failed, and would only fail again),
    nor where the fingers' goal itself was in collision (a closing that ends in the table
    under a spoon ends there from any opening)."""
    if not opened or (isinstance(failure, GripperPathBlocked) and failure.path_fraction == 1.0):
        return False
    if isinstance(failure, GripperMetOneSide):
        return True
    fingers = robot.gripper_links(arm)
    links = {link for link, _ in getattr(failure, "colliding_pairs", None) or ()}
    return bool(links & fingers) and not links & (robot.hand_links(arm) - fingers)


def closed_into_surface(failure: Exception) -> bool:
    """Whether ``failure`` (a pick's, with its tries as ``causes``) holds a try whose
    fingers closed into the surface under the thing (:func:`_closed_into_surface`): the
    thing's stands may take it grasped higher (``pick_up_object``'s ``raised``)."""
    if not isinstance(failure, PickUpFailed) or failure.object_name is None:
        return False
    robot = current_robot()
    return any(
        _closed_into_surface(robot, arm, cause, failure.object_name)
        for cause in failure.causes or ()
        for arm in robot.grasping_arms()
    )


def _closed_into_surface(robot: KnownRobot, arm: str, failure: Exception, name: str) -> bool:
    """Whether ``failure`` is a grip whose closed goal itself lay in collision, each pair a
    finger of ``arm`` and something other than ``name`` (the table under a spoon): from a
    little higher the fingers close on the thing above the surface."""
    if not isinstance(failure, GripperPathBlocked) or failure.path_fraction != 1.0:
        return False
    fingers = robot.gripper_links(arm)
    pairs = failure.colliding_pairs or ()
    return bool(pairs) and all(link in fingers and other != name for link, other in pairs)


def _to_pre_grasp(arm: str, pre_grasp: PoseStamped, **mode: str) -> None:
    """Move the open hand to ``pre_grasp``; where the head, turned down at the object, is
    in the way (a Stretch's lift carriage, raised to a table's height, meets its tilted
    head), look ahead and move again."""
    try:
        _move(arm, pre_grasp, **mode)
    except ManipulationLowLevelFailure as failure:
        if not (neck_in_the_way(failure) and look_ahead()):
            raise
        _move(arm, pre_grasp, **mode)


def _fingers_meet_body(arm: str, blocked: GripperPathBlocked) -> bool:
    """Whether every pair ``blocked`` names is a finger of ``arm`` and a link of the
    robot's body (no arm's, hand's or neck's: those and the world a move may not clear)."""
    robot = current_robot()
    fingers, limbs = robot.gripper_links(arm), robot.limb_links()
    pairs = blocked.colliding_pairs or ()
    return bool(pairs) and all(
        other in fingers and link not in limbs for link, other in pairs
    )  # (robot link, what it meets): a robot meeting itself names its own link second


def _lifted(
    arm: str, lift: PoseStamped, name: str, grasp: PoseStamped | None = None
) -> PoseStamped:
    """Lift the gripped ``name`` to ``lift``; where the head, still turned down at it, is
    in the way (a Stretch's lift carriage meets its tilted head on a lift out of a drawer),
    look ahead and lift again. With ``grasp`` (a try from a line stand), a lift out of the
    arm's reach is tried lower (:data:`LOWER_LIFTS` of its rise over ``grasp``): a shelf
    near the top of the arm's range leaves less room. Where the hand went."""
    try:
        _move(arm, lift, **GRASPING, touching=name)
        return lift
    except ManipulationLowLevelFailure as failure:
        if neck_in_the_way(failure) and look_ahead():
            _move(arm, lift, **GRASPING, touching=name)
            return lift
        if grasp is None or not isinstance(failure, ManipulationPoseUnreachable):
            raise
        for share in LOWER_LIFTS:
            lower = towards(lift, grasp, share)
            with contextlib.suppress(ManipulationPoseUnreachable):
                _move(arm, lower, **GRASPING, touching=name)
                return lower
        raise


def _gripped(arm: str, name: str, choice: ObjectGrasp) -> ObjectGrasp:
    """Grip ``name`` at ``choice``'s grasp pose; where the fingers meet it on one side
    only, move the open hand by the shift the failure names and grip again (at most
    :data:`CENTRINGS` times). The grasp as gripped: its grasp and lift poses moved so.

    Raises:
        GripperMetOneSide: still one-sided after the centrings (or no shift was named).
        PickUpFailed: the hand gripped another object.
    """
    for centring in range(CENTRINGS + 1):
        try:
            gripped = perform(a.motion(type="gripping", gripper=arm))
            break
        except GripperMetOneSide as one_sided:
            if one_sided.shift is None or centring == CENTRINGS:
                raise
            choice = _shifted(choice, one_sided.shift)
            _move(arm, choice.grasp_pose, **GRASPING, touching=name)
    if isinstance(gripped, str) and gripped != name:  # projection names what it holds
        perform(a.motion(type="opening", gripper=arm))
        raise PickUpFailed(f"the {arm} hand gripped {gripped!r}, not {name!r}", object_name=name)
    return choice


def _shifted(choice: ObjectGrasp, shift: tuple[float, float, float]) -> ObjectGrasp:
    """``choice`` with its grasp and lift poses (``map``) moved by ``shift`` [m]."""

    def moved(pose: PoseStamped) -> PoseStamped:
        x, y, z = pose.position
        return replace(pose, position=(x + shift[0], y + shift[1], z + shift[2]))

    return replace(choice, grasp_pose=moved(choice.grasp_pose), lift=moved(choice.lift))


def _let_go(robot: KnownRobot, name: str) -> None:
    """Open each hand that still grips ``name`` after the last try failed: a try whose
    lift failed leaves it gripped where it lies, and only the next try's opening let it
    go (Boxy's right hand kept a spoon its lift could not raise out of an east drawer,
    parked with it and drove on; no stand then saw it in the drawer). Best effort."""
    for arm, held in robot.held_objects(robot.grasping_arms()).items():
        if held == name:
            with contextlib.suppress(GripperLowLevelFailure):
                perform(a.motion(type="opening", gripper=arm))


def _back_out(name: str, way_out: _WayOut) -> PlanFailure | None:
    """Take a hand that the last failed try left at its grasp back out to its pre-grasp,
    open: parking or driving from a grasp deep in a drawer ran into the drawer above in
    every plan (the Stretch's fingers round a cup its grip met on one side, every later
    motion blocked). Best effort: a way out that fails is returned, not raised, so that
    the pick's own failure, with every try's cause, is what the caller sees (an arm that
    reaches with its base backs out by a drive, whose failure had replaced it: the
    drafted Stretch at the fridge's milk); None where it went or nothing was to do."""
    if way_out.arm is None or way_out.pre_grasp is None:
        return None
    with contextlib.suppress(GripperLowLevelFailure):
        perform(a.motion(type="opening", gripper=way_out.arm))
    try:
        _move(way_out.arm, way_out.pre_grasp, **GRASPING, touching=name)
    except ManipulationLowLevelFailure:
        return None  # as before: the next step names what still fails
    except NavigationLowLevelFailure as failure:
        return None if _out_by_halves(name, way_out.arm, way_out.pre_grasp) else failure
    return None


def _out_by_halves(name: str, arm: str, pre_grasp: PoseStamped) -> bool:
    """Whether the open hand went out to ``pre_grasp`` by way of the point halfway there
    (:data:`BACK_OUT_SHARE`), after the whole way failed: the drafted Stretch, its base
    turned at the fridge's milk, could not take the fingers straight back all 10 cm (its
    telescope drawn in, the base only drives along its heading), and the drive that turns
    it swept a finger 5.1 mm into the milk; from halfway the turn clears it. Best effort."""
    here = transform_pose(PoseStamped(current_robot().tool_frame(arm)), "map")
    try:
        _move(arm, towards(pre_grasp, here, BACK_OUT_SHARE), **GRASPING, touching=name)
        _move(arm, pre_grasp, **GRASPING, touching=name)
    except (ManipulationLowLevelFailure, NavigationLowLevelFailure):
        return False
    return True


def _hand_out(robot: KnownRobot, name: str, way_out: _WayOut, causes: list[Exception]) -> None:
    """Let go, take the hand out to its pre-grasp and park, before a try from elsewhere; a
    way out that failed is added to ``causes``."""
    _let_go(robot, name)
    stuck = _back_out(name, way_out)
    if stuck is not None:
        causes.append(stuck)
    way_out.arm = None
    with contextlib.suppress(PlanFailure):
        park_arms()


def _drawn_back(held: Held, choice: ObjectGrasp) -> Held:
    """Draw the lifted hand back along its approach line, as high as it was lifted, to
    :data:`DRAW_BACK` past its pre-grasp: from a line stand the telescope does it, and a
    drive with the hand still in the shelf (the fridge's milk held over its shelf) ran into
    the shelf.

    Raises:
        ManipulationLowLevelFailure: the way back is blocked or out of reach.
    """
    x, y, z = _way_back(choice).position
    rise = held.lifted.position[2] - held.grasp_pose.position[2]
    back = replace(held.lifted, position=(x, y, z + rise))
    _move(held.arm, back, **GRASPING, touching=held.object_name)
    return replace(held, lifted=back)


def _way_back(choice: ObjectGrasp) -> PoseStamped:
    """``choice``'s pre-grasp moved :data:`DRAW_BACK` further off its grasp (``map``)."""
    pre, grasp = np.asarray(choice.pre_grasp.position), np.asarray(choice.grasp_pose.position)
    depth = float(np.linalg.norm(pre - grasp))
    share = (depth + DRAW_BACK) / max(depth, 1e-9)
    return towards(choice.pre_grasp, choice.grasp_pose, share)


def _line_stand(robot: KnownRobot, arm: str, choice: ObjectGrasp) -> PoseStamped | None:
    """Where ``arm`` takes its hand from ``choice``'s pre-grasp (and :data:`DRAW_BACK` past
    it) to its grasp and back by its level telescope alone (``line_stand/5``): the drafted
    Stretch's base, turned a little at the fridge's milk with its telescope drawn in,
    backed its hand out only by a drive that turned the fingers into the fridge. None
    where there is none (no such telescope, an approach not level, or no world to ask)."""
    try:
        row = LINE_STAND.first(
            current_kb(), robot=robot.name, arm=arm, out=_way_back(choice),
            grasp=choice.grasp_pose,
        )  # fmt: skip
    except UnknownPredicateError:
        return None
    return None if row is None else row.stand


def grasp_object(
    object: ObjectDesignator | str,  # noqa: A002 - CRAM's key
    arm: str | None = None,
    grasp: str | None = None,
) -> Held:
    """Grasp the (detected) object where it stands: open, approach, close on it; CRAM's
    and PyCRAM's ``grasping`` (:func:`pick_up_object` without the lift)."""
    return pick_up_object(object, arm, grasp, lift=False)


def pick_up_object(
    object: ObjectDesignator | str,  # noqa: A002 - CRAM's key
    arm: str | None = None,
    grasp: str | None = None,
    lift: bool = True,
    out_of: tuple[str, str] | None = None,
    nearer: bool = False,
    raised: bool = False,
) -> Held:
    """Pick up the (detected) object with ``arm`` and ``grasp``, or the first that works
    (``lift`` False: grasp it where it stands; ``out_of``: the opened drawer, environment
    and link, it lies in, which the lift must clear; ``nearer``: after every usual try
    failed, each again from a pre-grasp and a lift nearer the grasp (a lift out of a drawer
    kept), then from a pre-grasp nearer still, ``plans/nearer_pre_grasp.py``).

    Raises:
        ObjectUngraspable: the only arm asked for is too narrow for every grasp.
        PickUpFailed: no arm and grasp picked it up; ``causes`` holds each try's failure.
            :class:`PickUpUnreachable` (also a ``ManipulationPoseUnreachable``) when every
            try was out of reach.
    """
    robot = current_robot()
    name, spec, pose = object_spec(object)
    causes: list[Exception] = []
    way_out = _WayOut()
    caught: list[tuple[str, ObjectGrasp]] = []  # grasps a finger was caught at
    dipped: list[tuple[str, ObjectGrasp]] = []  # grasps whose fingers closed into a surface
    arms = arms_nearest_first(robot, pose, arm)
    tried: list[tuple[str, ObjectGrasp]] = []
    for choice_arm in arms:
        try:
            choices = grasp_choices(robot, spec, choice_arm, grasp)
        except ObjectUngraspable as failure:
            if arm is not None:
                raise
            causes.append(failure)
            continue
        for grasped in choices:
            way_out.opened = False  # until this try's hand opens
            try:
                choice = grasped
                if lift and out_of is not None:
                    choice = _lifted_out(robot, name, choice_arm, grasped, out_of)
                tried.append((choice_arm, choice))
                return _try_grasp(robot, name, choice_arm, choice, pose, lift, way_out)
            except TRIES as failure:
                causes.append(failure)
                if _finger_caught(robot, choice_arm, failure, way_out.opened):
                    caught.append((choice_arm, grasped))
                if _closed_into_surface(robot, choice_arm, failure, name):
                    dipped.append((choice_arm, choice))
            except PickUpFailed as failure:
                causes.append(failure)
    for choice_arm, choice in dipped if raised else []:  # then higher, where the fingers
        # closed into the surface under the thing
        for rise in RAISES:
            _hand_out(robot, name, way_out, causes)
            try:
                higher = _shifted(choice, (0.0, 0.0, rise))
                return _try_grasp(robot, name, choice_arm, higher, pose, lift, way_out)
            except (*TRIES, PickUpFailed) as failure:
                causes.append(failure)
    for choice_arm, choice in caught:  # only after every try: the hand opened part way,
        _hand_out(robot, name, way_out, causes)  # from parking (at the last try's grasp the
        # fingers closing part way met the drawer)
        try:
            if lift and out_of is not None:
                choice = _lifted_out(robot, name, choice_arm, choice, out_of)
            fraction = PART_WAY if choice.grasp == "rim" else HALF_WAY
            return _try_grasp(robot, name, choice_arm, choice, pose, lift, way_out, fraction)
        except (*TRIES, PickUpFailed) as failure:
            causes.append(failure)
    nearer_tries = [(s, a, c) for s in (NEARER_SHARE, NEAREST_SHARE) for a, c in tried]
    for share, choice_arm, choice in nearer_tries if nearer else []:  # then each from
        # nearer the grasp, then from nearer still
        try:
            keep = 1.0 if out_of is not None else NEARER_LIFT_SHARE  # a drawer's lift clears it
            nearer_choice = nearer_pre_grasp(choice, share, lift_share=keep)
            return _try_grasp(
                robot, name, choice_arm, nearer_choice, pose, lift, way_out, near=True
            )
        except TRIES as failure:
            causes.append(failure)
        except PickUpFailed as failure:
            causes.append(failure)
    for choice_arm, choice in tried:  # then each from a stand on its approach line
        stand = _line_stand(robot, choice_arm, choice)
        if stand is None:
            continue
        _hand_out(robot, name, way_out, causes)
        try:
            navigate_empty_hand_up(stand)
            held = _try_grasp(
                robot, name, choice_arm, choice, pose, lift, way_out, lower_lifts=True
            )
            return _drawn_back(held, choice) if lift else held
        except TRIES as failure:
            causes.append(failure)
        except PickUpFailed as failure:
            causes.append(failure)
    for choice_arm, choice in caught if out_of is not None else []:  # last, in a drawer,
        # a grasp the half-open hand was caught at too (a rim grasp's retry opened a third
        # already); not on a table, where the milk's narrow tries, parked from, left the
        # drafted Stretch no later stand that took it (household 0's clearing)
        if choice.grasp == "rim":
            continue
        _hand_out(robot, name, way_out, causes)
        try:
            if lift and out_of is not None:
                choice = _lifted_out(robot, name, choice_arm, choice, out_of)
            return _try_grasp(robot, name, choice_arm, choice, pose, lift, way_out, NARROW)
        except (*TRIES, PickUpFailed) as failure:
            causes.append(failure)
    _let_go(robot, name)
    stuck = _back_out(name, way_out)
    unreachable = bool(causes) and all(isinstance(c, ManipulationPoseUnreachable) for c in causes)
    raise (PickUpUnreachable if unreachable else PickUpFailed)(
        f"no arm of {arms} picked up {name!r}"
        + (f" with grasp {grasp!r}" if grasp else "")
        + f" in {len(causes)} tries (causes: "
        + ", ".join(sorted({type(c).__name__ for c in causes}))
        + ")"
        + ("" if stuck is None else f"; the hand then stayed at its grasp: {stuck}"),
        object_name=name,
        causes=causes if stuck is None else [*causes, stuck],
    ) from stuck

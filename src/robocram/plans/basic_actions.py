"""The small actions every fetch-and-deliver plan is made of: each PERFORMs one kind of motion.

Everything robot-specific (which arms there are, their parking joints, the torso) comes
from the interface predicates in the current knowledge base.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import Any

from robocram.designators import ObjectDesignator, a, an
from robocram.execution import perform
from robocram.execution.failures import (
    ManipulationLowLevelFailure,
    ManipulationPathBlocked,
    ManipulationPoseUnreachable,
    NavigationLowLevelFailure,
    PlanFailure,
    PtuGoalNotReached,
    PtuPathBlocked,
    TorsoPathBlocked,
)
from robocram.plans.errors import PlanSetupError
from robocram.plans.known_robot import KnownRobot, current_robot
from robocram.plans.tilt_limit_look import seen_at_tilt_limit
from robocram.tf import Pose, PoseStamped, transform_pose

# [m] (forward, left) base moves, in its frame where parking first failed, before each
# further try: back away from what the hand just worked at, then sideways from a wall
# the torso's heights, as fractions of its travel, from which a blocked look from the top is
# tried again, highest first (an HSR's head turned down meets its parked hand with the
# lift high, and sees nothing in a drawer with it low)
LOOK_HEIGHTS = (0.5, 0.25, 0.0)
AHEAD = (1.0, 0.0, 0.0)  # the direction a robot looks in to drive, in its base frame
PARKING_BACKOFFS = ((-0.15, 0.0), (-0.45, 0.0), (0.0, 0.2), (0.0, -0.2), (-0.2, 0.2), (-0.2, -0.2))
PARKING_LIFTS = (0.3, 0.15)  # [m] the hand rises this far (the first it can) when no backoff
# helped: an arm low over an open drawer drags through its wall
PARKING_PULLS = (0.3, 0.15)  # [m] the hand comes in towards the base (level, the first it
# can) when rising did not help either: a hand left deep in a fridge at the edge of its reach


def navigate(target: object) -> Any:
    """Drive the base to ``target`` (a pose, a PoseStamped or a location designator)."""
    return perform(a.motion(type="going", target=target))


def park_arms(arm: str | None = None) -> list[str]:
    """Put ``arm`` (default: every arm) into its parking configuration; return the arms."""
    robot = current_robot()
    parked = []
    for name in robot.arms():
        pose = robot.parking(name)
        if pose is None or (arm is not None and name != arm):
            continue
        if pose.joint_states:
            states = [[joint, value] for joint, value in pose.joint_states]
            _park(robot, name, states)
        parked.append(name)
    if arm is not None and not parked:
        raise PlanSetupError(f"{robot.name} has no arm {arm!r} with a parking configuration")
    return parked


def neck_in_the_way(failure: ManipulationLowLevelFailure) -> bool:
    """Whether ``failure`` names one of the robot's neck links among what the arm hits."""
    if not isinstance(failure, ManipulationPoseUnreachable):
        return False
    neck = set(current_robot().neck_links())
    return any(link in neck for pair in failure.colliding_pairs or () for link in pair)


def look_ahead() -> bool:
    """Look ahead (:data:`AHEAD`), as a robot does to drive; whether the head turned."""
    try:
        perform(a.motion(type="looking", direction=AHEAD))
    except PlanFailure:
        return False
    return True


def park_neck() -> bool:
    """Turn the neck (a pan-tilt head or a neck arm) to its parking configuration from the
    KB, as the arms are parked; whether it turned (False: it has none, or the turn failed)."""
    parking = current_robot().neck_parking()
    if parking is None or not parking.joint_states:
        return False
    states = [[joint, value] for joint, value in parking.joint_states]
    try:
        perform(a.motion(type="looking", configuration=states))
    except PlanFailure:
        return False
    return True


def _park(robot: KnownRobot, arm: str, states: list[list[object]]) -> None:
    """Park ``arm``; when its parking pose would hit the head, still turned down at what the
    robot looked at (an HSR's, with its lift up), look ahead and try again; when it would
    hit what the robot stands at (a table the hand just put something on, a wall beside
    it), move the base away and try again: back first, then to either side
    (:data:`PARKING_BACKOFFS`); a move that cannot be driven is skipped. When no move
    helped, the hand rises (:data:`PARKING_LIFTS`) and the moves are tried again: a hand
    low in an open drawer is dragged through its wall by every move, or by all but a short
    one that leaves the base too near the drawer (a Fetch beside a drawer it put a cup
    into: 15 cm back, the parked elbow still met it). The parking failure is raised when
    every move was tried. When rising did not help either, the hand comes in towards the
    base, level (:data:`PARKING_PULLS`), and the moves are tried once more: a PR2 that put
    the milk under the fridge's shelf from beside its open door could not raise its hand
    there, the parked forearm met the door and every move dragged the hand through the
    fridge."""
    try:
        perform(a.motion(type="moving-arm-joints", arm=arm, configuration=states))
        return
    except ManipulationPathBlocked as failure:
        blocked = failure
    if neck_in_the_way(blocked) and look_ahead():
        try:
            perform(a.motion(type="moving-arm-joints", arm=arm, configuration=states))
            return
        except ManipulationPathBlocked as failure:
            blocked = failure
    still = _park_backing_off(robot, arm, states, blocked)
    if still is not None and lift_hand(robot, arm):
        still = _park_backing_off(robot, arm, states, still)
    if still is not None and _pull_hand_in(robot, arm):
        still = _park_backing_off(robot, arm, states, still)
    if still is not None:
        raise still


def _park_backing_off(
    robot: KnownRobot, arm: str, states: list[list[object]], blocked: ManipulationPathBlocked
) -> ManipulationPathBlocked | None:
    """Try parking after each of :data:`PARKING_BACKOFFS` (from where the base stands now);
    the last parking failure (None: parked)."""
    origin = transform_pose(PoseStamped(robot.base_frame()), "map").pose
    for forward, left in PARKING_BACKOFFS:
        moved = origin * Pose((forward, left, 0.0))
        try:
            perform(a.motion(type="going", target=PoseStamped.from_pose("map", moved)))
        except NavigationLowLevelFailure:
            continue
        try:
            perform(a.motion(type="moving-arm-joints", arm=arm, configuration=states))
            return None
        except ManipulationPathBlocked as failure:
            blocked = failure
    return blocked


def lift_hand(robot: KnownRobot, arm: str) -> bool:
    """Raise ``arm``'s hand straight up, its orientation kept, by the first of
    :data:`PARKING_LIFTS` it can; whether it rose."""
    tool = transform_pose(PoseStamped(robot.tool_frame(arm)), "map").pose
    x, y, z = tool.position
    return _first_hand_move(arm, (Pose((x, y, z + r), tool.orientation) for r in PARKING_LIFTS))


def _pull_hand_in(robot: KnownRobot, arm: str) -> bool:
    """Bring ``arm``'s hand level towards the base's middle, its orientation kept, by the
    first of :data:`PARKING_PULLS` it can; whether it moved."""
    tool = transform_pose(PoseStamped(robot.tool_frame(arm)), "map").pose
    base = transform_pose(PoseStamped(robot.base_frame()), "map").pose
    x, y, z = tool.position
    dx, dy = base.position[0] - x, base.position[1] - y
    reach = math.hypot(dx, dy)
    if reach < 1e-6:
        return False
    shares = (min(pull, reach) / reach for pull in PARKING_PULLS)
    return _first_hand_move(
        arm, (Pose((x + k * dx, y + k * dy, z), tool.orientation) for k in shares)
    )


def _first_hand_move(arm: str, poses: Iterable[Pose]) -> bool:
    """Move ``arm``'s tool to the first of ``poses`` (map) it reaches; whether it moved."""
    for pose in poses:
        target = a.location(pose=PoseStamped.from_pose("map", pose))
        try:
            perform(a.motion(type="moving-tcp", arm=arm, target=target))
        except ManipulationLowLevelFailure:
            continue
        return True
    return False


def move_torso(joint_angle: float | str) -> Any:
    """Move the torso to ``joint_angle`` [m | rad], or to its ``upper``/``lower`` limit."""
    if isinstance(joint_angle, str):
        robot = current_robot()
        limit = None
        if joint_angle in ("upper", "lower"):
            limit = robot.torso_limit("upper" if joint_angle == "upper" else "lower")
        if limit is None:
            raise PlanSetupError(
                f"torso goal {joint_angle!r} is no number and not upper/lower of a torso "
                f"joint of {robot.name}"
            )
        joint_angle = limit
    return perform(a.motion(type="moving-torso", joint_angle=joint_angle))


GRIPPER_MOTIONS = {"open": "opening", "close": "closing"}  # CRAM's :open and :close


def set_gripper(gripper: str, motion: str | float) -> object:
    """Open or close ``gripper`` (an arm's name or side), or move it to a joint value [m |
    rad]: CRAM's ``setting-gripper`` action. Closing stops on what is between the fingers
    but does not hold it (``gripping`` does)."""
    if isinstance(motion, str):
        kind = GRIPPER_MOTIONS.get(motion)
        if kind is None:
            raise PlanSetupError(
                f"setting-gripper motion {motion!r} is neither of {sorted(GRIPPER_MOTIONS)} "
                "nor a joint value [m | rad]"
            )
        return perform(a.motion(type=kind, gripper=gripper))
    return perform(a.motion(type="moving-gripper-joint", gripper=gripper, joint_angle=motion))


def look(target: object) -> Any:
    """Point the camera at ``target``."""
    return perform(a.motion(type="looking", target=target))


# looks that a lower torso may let succeed: the head blocked, or tilted down to its limit
LOWER_TO_LOOK = (PtuPathBlocked, PtuGoalNotReached)


def _lowering_helps(failure: PlanFailure) -> bool:
    """Whether a lower torso may let a failed look succeed: the head was blocked, or its
    tilt stopped at its limit above the target (Armar6's head tilts 46 degrees down)."""
    return isinstance(failure, PtuPathBlocked) or (
        isinstance(failure, PtuGoalNotReached) and failure.below_tilt
    )


def look_to_tilt_limit(target: object) -> object:
    """Point the camera at ``target``; a head that stops at its tilt limit above it but
    has it in the lower part of its view (:func:`seen_at_tilt_limit`) has looked: the
    joints it turned to.

    Raises:
        PtuGoalNotReached: the head could not turn to the target, and the target is not
            so in view.
    """
    return _or_at_tilt_limit(look, target)


def _or_at_tilt_limit(looking: Callable[[object], object], target: object) -> object:
    """``looking(target)``; where it stopped at the tilt limit with the target in the
    lower part of the view (:func:`seen_at_tilt_limit`), the joints the head turned to."""
    try:
        return looking(target)
    except PtuGoalNotReached as failure:
        if seen_at_tilt_limit(failure):
            return failure.reached
        raise


def look_lowering(target: object) -> object:
    """Point the camera at ``target``, lowering the torso where that helps
    (:func:`_look_lowering`); where the head still stops at its tilt limit above the
    target (TALOS has no torso to lower), the look counts as had if the target lies in
    the lower part of the view (:func:`seen_at_tilt_limit`): the joints it turned to.

    Raises:
        PtuPathBlocked: the head is blocked at the lowest step too, or there is no torso
            to lower.
        PtuGoalNotReached: the head cannot tilt down to the target at the lowest step,
            and the target is not in the lower part of its view.
    """
    return _or_at_tilt_limit(_look_lowering, target)


def _look_lowering(target: object) -> object:
    """Point the camera at ``target``; where the head is blocked (an HSR whose lift an
    earlier reach left up carries its parked hand into the head turned down: 8 of 50
    kitchen mug fetches failed so), or cannot tilt down to it, lower the torso in steps
    (:data:`LOOK_HEIGHTS` of its travel, only those below where it is) until the head can
    look. The head looks ahead first: still turned down at what the robot looked at
    before, it would meet the hand on the torso's way down.

    Raises:
        PtuPathBlocked: the head is blocked at the lowest step too, or there is no torso
            to lower.
        PtuGoalNotReached: the head cannot tilt down to the target at the lowest step.
    """
    try:
        return look(target)
    except LOWER_TO_LOOK as failure:
        heights = heights_below(current_robot())
        if not heights or not _lowering_helps(failure):
            raise
    look_ahead()
    for height in heights[:-1]:
        move_torso(height)
        try:
            return look(target)
        except LOWER_TO_LOOK as failure:
            if not _lowering_helps(failure):
                raise
    move_torso(heights[-1])
    return look(target)


def heights_below(robot: KnownRobot) -> list[float]:
    """The torso heights [m | rad] of :data:`LOOK_HEIGHTS` below where it is now."""
    upper, lower = robot.torso_limit("upper"), robot.torso_limit("lower")
    now = robot.torso_position()
    if upper is None or lower is None or now is None:
        return []
    heights = [lower + fraction * (upper - lower) for fraction in LOOK_HEIGHTS]
    return [h for h in heights if h < now - 1e-6]


def look_from_above(target: object, looked: bool = False) -> None:
    """Raise the torso to its top and look at ``target``, for a view from above (into a
    drawer, down on a table). Where the robot's own arm is in the way (an HSR's lift raises
    its parked hand twice as fast as its head, into the head turned down), a raise that is
    blocked moves nothing and the robot looks from where it is (not again if it
    ``looked`` already), and after a look that is blocked the torso goes down in steps
    (:data:`LOOK_HEIGHTS` of its travel) until the head can look from there; so too
    after a look whose tilt stops above the target (a head that tilts down too little)."""
    robot = current_robot()
    upper = robot.torso_limit("upper")
    raised = upper is not None
    if upper is not None:
        try:
            move_torso(upper)
        except TorsoPathBlocked:
            raised = False
    if not raised and looked:
        return
    lower = robot.torso_limit("lower")
    heights = [] if upper is None or lower is None or not raised else LOOK_HEIGHTS
    for fraction in (None, *heights):
        if fraction is not None:
            assert upper is not None and lower is not None
            lower_torso(lower + fraction * (upper - lower))
        try:
            look(target)
            return
        except LOWER_TO_LOOK as failure:
            if fraction == 0.0 or not heights or not _lowering_helps(failure):
                raise


def lower_torso(height: float) -> None:
    """Move the torso down to ``height``; where the head, still turned down at what the
    robot looked at, meets the parked hand on the way (an HSR's lift goes down twice as
    fast as its head), look ahead and move again."""
    try:
        move_torso(height)
    except TorsoPathBlocked:
        if not look_ahead():
            raise
        move_torso(height)


def detect(object: ObjectDesignator | str) -> ObjectDesignator:  # noqa: A002 - CRAM's key
    """Detect the object (a designator, or an object type); the perceived designator."""
    desig = object if isinstance(object, ObjectDesignator) else an.object(type=object)
    return perform(a.motion(type="detecting", object=desig))

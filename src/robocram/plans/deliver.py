"""Delivering: stand beside the placing spot with the object over it, put it down.

The target is a location designator (``a.location(on=..., for_=...)``) or a pose. For
each placing spot (bounded by ``place_retries``) the robot tries stands that hold the
object over the spot as the arm holds it now (:func:`placing_stands`): a stand where it
would collide is skipped at once; a stand where placing fails gives the next one, at most
``stand_retries`` per spot (a way there blocked only by the empty other hand, still round
what it just put down, is driven again with that hand lifted). With ``reach_stands`` the
stands from which the arm reaches the spot by IK (a ``reachable_for`` location) come after
those: a spot deep in a fridge is reached slanting past its open door, not with the arm as
it holds the thing now. When all fail, :class:`DeliveryExhausted` (an
``ObjectUndeliverable``) carries every cause in order. A put that let the object go and
then failed ends the delivery (:class:`ObjectLetGo`): the next stands would only move an
empty hand, maybe one still inside a drawer.
"""

from __future__ import annotations

import contextlib
import itertools
from collections.abc import Iterator
from typing import Any

from robocram.designators import ObjectDesignator, a
from robocram.designators.errors import DesignatorError
from robocram.execution import perform
from robocram.execution.failures import (
    ManipulationLowLevelFailure,
    NavigationPoseUnreachable,
    PlanFailure,
)
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import look_ahead, neck_in_the_way
from robocram.plans.empty_hand_up import navigate_empty_hand_up
from robocram.plans.errors import DeliveryExhausted, ObjectLetGo, PlanArgumentError
from robocram.plans.known_robot import current_robot
from robocram.plans.location_poses import location_poses, next_pose
from robocram.plans.pick_object import GRASPING, Held
from robocram.plans.place_object import held_object, place_object
from robocram.plans.stands import map_pose, placing_stands
from robocram.plans.upright import upright_put
from robocram.tf import Pose, PoseStamped

STAND_RETRIES = 3  # stands per placing spot where placing is tried
PLACE_RETRIES = 6  # placing spots tried (a spot in the middle of a table has no stand)
REACH_STANDS = 6  # stands from the reachable_for costmap tried per spot, at most
CARRY_CLEARANCE = 0.08  # [m] the held object's frame is carried this far over the spot


def _place_at(held: Held, spot: Pose, arm: str | None) -> Any:
    """Put the held object's frame at ``spot``, keeping the heading it has in the hand now;
    where ``spot`` (as a location gives it: turned as the object was held then, its lowest
    point on the surface) is askew, upright (:func:`upright_put`): a try that levelled it
    on its way down and failed leaves it level in the hand, the spot's height still that
    of the askew one."""
    held_so = Pose(spot.position, map_pose(held.object_name).orientation)
    put = PoseStamped.from_pose("map", upright_put(held.object_name, spot) or held_so)
    return place_object(held, put, arm=arm)


def _lift(held: Held, rise: float) -> None:
    """Raise the held object by ``rise`` [m], the hand's orientation kept."""
    tool = map_pose(held.tool_frame)
    x, y, z = tool.position
    lifted = PoseStamped.from_pose("map", Pose((x, y, z + rise), tool.orientation))
    perform(
        a.motion(
            type="moving-tcp",
            arm=held.arm,
            target=a.location(pose=lifted),
            **GRASPING,
            touching=held.object_name,
        )  # fmt: skip
    )


def _carry_above(held: Held, spot: Pose) -> None:
    """Lift the held object over ``spot``'s height (plus a margin) if it hangs lower.

    An object taken out of a drawer is held below a table's top; driving up to the table
    with it would run the hand into the table. A head still turned down at what was
    picked up may be in the lift's way (a Stretch's lift carriage meets its tilted head):
    then the robot looks ahead, as it does to drive, and lifts again.
    """
    rise = spot.position[2] + CARRY_CLEARANCE - map_pose(held.object_name).position[2]
    if rise <= 0.0:
        return
    try:
        _lift(held, rise)
    except ManipulationLowLevelFailure as failure:
        if not (neck_in_the_way(failure) and look_ahead()):
            raise
        _lift(held, rise)


def _stands(held: Held, spot: Pose, arm: str | None, reach_stands: bool) -> Iterator[Pose]:
    """The stands to put ``held`` down at ``spot`` from: those holding it over the spot as
    the arm holds it now, then (``reach_stands``) the costmap's that reach it by IK; held
    askew, only those: it goes down upright, not as held (:func:`upright_put`)."""
    robot = current_robot()
    held_so = Pose(spot.position, map_pose(held.object_name).orientation)
    upright = upright_put(held.object_name, spot)
    if upright is None:
        yield from placing_stands(robot, held.object_name, spot)
        if not reach_stands:
            return
    keys: dict[str, str] = {"arm": arm} if arm is not None else {}
    target = PoseStamped.from_pose("map", upright or held_so)
    with contextlib.suppress(DesignatorError):  # no stand reaches it: the spot fails
        yield from itertools.islice(
            location_poses(a.location(reachable_for=robot.name, target=target, **keys)),
            REACH_STANDS,
        )


def holds(held: Held) -> bool:
    """Whether ``held``'s hand still holds its thing (the KB's ``attached/4``)."""
    return current_robot().held_objects([held.arm]).get(held.arm) == held.object_name


def _let_go(held: Held, causes: list[Exception]) -> ObjectLetGo:
    """The failure of a delivery whose hand no longer holds its thing."""
    last = f": {causes[-1]}" if causes else ""
    return ObjectLetGo(
        f"{held.object_name} is no longer in the {held.arm} hand{last}",
        object_name=held.object_name,
        causes=tuple(causes),
    )


def _try_spot(
    held: Held,
    spot: Pose,
    arm: str | None,
    stand_retries: int,
    log: AttemptLog,
    reach_stands: bool = False,
) -> list[Exception]:
    """Try the stands of one spot; the failures met (empty: the object was placed).

    Raises:
        ObjectLetGo: a put let the object go and failed.
    """
    causes: list[Exception] = []
    try:
        _carry_above(held, spot)
    except ManipulationLowLevelFailure as failure:  # carried low: some stands will collide
        causes.append(failure)
    tried = 0
    for stand in _stands(held, spot, arm, reach_stands):
        try:
            navigate_empty_hand_up(stand)
        except NavigationPoseUnreachable as failure:  # a stand in the way: the next turn
            log.record("deliver", stand, failure)
            causes.append(failure)
            continue
        tried += 1
        try:
            _place_at(held, spot, arm)
        except PlanFailure as failure:
            log.record("deliver", stand, failure)
            causes.append(failure)
            if not holds(held):
                raise _let_go(held, causes) from failure
            if tried >= stand_retries:
                return causes
            continue
        log.record("deliver", stand, None)
        return []
    return causes


def deliver(
    object: Held | ObjectDesignator | str,  # noqa: A002 - CRAM's key
    target: object,
    arm: str | None = None,
    stand_retries: int = STAND_RETRIES,
    place_retries: int = PLACE_RETRIES,
    log: AttemptLog | None = None,
    reach_stands: bool = False,
) -> Pose:
    """Place the held object at ``target`` (a location designator or a pose); the spot.

    ``object`` is what fetching returned (a :class:`Held`), or the held object's name.
    ``reach_stands``: after the stands that hold it over a spot as the arm holds it now,
    try those from which the arm reaches the spot (a spot inside a container).

    Raises:
        DeliveryExhausted: no spot within ``place_retries`` and no stand within
            ``stand_retries`` per spot let the robot put the object down.
        ObjectLetGo: the hand holds the object no longer (a put let it go and failed,
            or it was let go before).
    """
    if stand_retries < 1 or place_retries < 1:
        raise PlanArgumentError(
            f"stand_retries and place_retries must be at least 1, got {stand_retries} "
            f"and {place_retries}"
        )
    log = log if log is not None else AttemptLog()
    held = held_object(object, arm)
    if not holds(held):
        raise _let_go(held, [])
    causes: list[Exception] = []
    spots = location_poses(target)
    for _ in range(place_retries):
        spot = next_pose(spots, causes)
        if spot is None:
            break
        failures = _try_spot(held, spot, arm, stand_retries, log, reach_stands)
        if not failures:
            return spot
        causes.extend(failures)
    raise DeliveryExhausted(
        f"could not deliver {held.object_name} to {target!r}: "
        + "; ".join(type(c).__name__ for c in causes[-5:]),
        target=target,
        causes=tuple(causes),
        attempts=len(log.of("deliver")),
    )

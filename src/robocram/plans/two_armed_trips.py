"""Two things to the table in one trip, one in each hand, for a robot with two arms.

The first thing is fetched and tucked into its arm's carrying pose (its parking
configuration, checked with what it holds), so it travels as part of the robot while the
other arm fetches the second and the stands for the second are checked. The robot drives
to the table once, puts the second thing down, brings the first out again to where the
arm held it just after picking it up (raised over the table) and puts it down too. The
table's free spots are found looking past the robot and what it holds (the ``on``
location's ``see_through``): its own arm over the table is no obstacle there.

Whenever the second thing cannot be fetched the first is put down alone and the second
is brought on a trip of its own, hands free; a second thing that cannot be put down
while the first is tucked is tried again once the first is on the table; a first thing
the arm cannot hold out again still tries the stands from which the arm reaches its spot.
A trip for two is meant to set no fewer things than two trips would.
"""

from __future__ import annotations

import contextlib
import math

from robocram.designators import a
from robocram.designators.errors import GroundingError
from robocram.execution import perform
from robocram.execution.failures import ManipulationLowLevelFailure, PlanFailure
from robocram.plans.basic_actions import navigate, park_arms
from robocram.plans.bringing import Visit, find_in_place, wanted_object
from robocram.plans.fetch import fetch
from robocram.plans.known_robot import current_robot
from robocram.plans.pick_object import GRASPING, Held
from robocram.plans.stands import map_pose, planar_pose, yaw_of
from robocram.plans.table_arrangement import Spot
from robocram.plans.table_trips import (
    TableSetting,
    bring_one,
    deliver_at_spot,
    deliver_to_spot,
    fetch_one,
)
from robocram.tf import Pose, PoseStamped, transform_pose

OVER_TABLE = 0.12  # [m] the first thing's frame comes out this far over its spot's height
BACK_OFF = 0.25  # [m] the base backs off this far when the arm cannot come out at the table


def other_arm(arm: str) -> str | None:
    """The current robot's other arm with a gripper than ``arm``, if it has one."""
    return next((other for other in current_robot().grasping_arms() if other != arm), None)


def _tucked(held: Held) -> Pose:
    """Put the arm holding ``held`` into its carrying pose; its tool pose before, in the
    base frame (where the arm holds it out again at the table)."""
    out = transform_pose(held.lifted, current_robot().base_frame()).pose
    park_arms(held.arm)
    return out


def _hold_out(held: Held, out: Pose, spot: Spot) -> None:
    """Bring the tucked ``held`` out again: the tool where ``out`` (base frame) puts it,
    raised so the thing hangs :data:`OVER_TABLE` over its spot, turned as it was just
    after the pick (a thing turned off the map's axes has wider bounds, and the ``on``
    location keeps their half diagonal free round it), else as ``out`` turns it; backs
    the base off once if the arm cannot come out where it stands."""
    for attempt in range(2):
        base = map_pose(current_robot().base_frame())
        tool = base * out
        turns = (held.lifted.pose.orientation, tool.orientation)
        for index, turn in enumerate(turns):
            thing = Pose(tool.position, turn) * held.object_in_tool
            rise = max(0.0, spot.pose.position[2] + OVER_TABLE - thing.position[2])
            x, y, z = tool.position
            target = PoseStamped.from_pose("map", Pose((x, y, z + rise), turn))
            try:
                _move_tool(held, target)
                return
            except ManipulationLowLevelFailure:
                if attempt and index == len(turns) - 1:
                    raise
        yaw = yaw_of(base)
        bx, by, _ = base.position
        navigate(planar_pose(bx - BACK_OFF * math.cos(yaw), by - BACK_OFF * math.sin(yaw), yaw))


def _move_tool(held: Held, target: PoseStamped) -> None:
    """Move the tool holding ``held`` to ``target`` (map)."""
    perform(
        a.motion(
            type="moving-tcp",
            arm=held.arm,
            target=a.location(pose=target),
            **GRASPING,
            touching=held.object_name,
        )  # fmt: skip
    )


def _put(held: Held, spot: Spot, done: TableSetting) -> None:
    """Deliver ``held`` to ``spot``, the table seen past the robot; record it placed.

    After the stands that hold it over the spot as the arm holds it now come those from
    which the arm reaches the spot: a thing picked up close to the body (a cup from a
    drawer's back) would put the other shoulder into the table."""
    deliver_at_spot(held, spot, done, see_through=(current_robot().name,), reach_stands=True)
    done.placed[held.object_name] = spot


def bring_two(first: Spot, second: Spot, visit: Visit, done: TableSetting) -> list[Exception]:
    """Bring the things of ``first`` and ``second`` in one trip if the robot can, else one
    by one; the failures (an empty list: both are set)."""
    try:
        held = fetch_one(first.type, visit, done)
    except PlanFailure as failure:  # no first thing: the second alone, as one-armed
        return [failure, *_alone(second, visit, done)]
    other = other_arm(held.arm)
    try:
        out = _tucked(held)
    except PlanFailure:  # too big to tuck in: this one alone, the second on its own trip
        other = None
    if other is None:
        return _deliver_alone(held, first, done) + _alone(second, visit, done)
    second_held = _second(second, other, visit, done, skip={*done.placed, held.object_name})
    if second_held is None:  # the other hand cannot take it: the first alone, the second
        return _held_out_alone(held, out, first, done) + _alone(second, visit, done)
    try:
        _put(second_held, second, done)
    except PlanFailure:  # with the first out of the way, once more after it
        return _held_out_alone(held, out, first, done) + _put_alone(second_held, second, done)
    return _held_out_alone(held, out, first, done, trip=[second_held.object_name])


def _second(spot: Spot, arm: str, visit: Visit, done: TableSetting, skip: set[str]) -> Held | None:
    """The thing of ``spot`` picked up with ``arm`` where the first was kept, or None.

    Only the visit's place is looked into, first from where the first was picked up: a
    thing kept elsewhere is searched for on a trip of its own, hands free, rather than all
    over the kitchen with one hand full.
    """
    found = find_in_place(wanted_object(spot.type), visit, done.log, skip, from_here=True)
    if found is None:
        return None
    try:
        return fetch(found[0], arm=arm, log=done.log, opened=found[1])
    except (PlanFailure, GroundingError):
        return None


def _held_out_alone(
    held: Held, out: Pose, spot: Spot, done: TableSetting, trip: list[str] | None = None
) -> list[Exception]:
    """Bring the tucked ``held`` out and put it at ``spot``; record the trip (with the
    things in ``trip`` put before on it); the failures. An arm that cannot come out
    still tries the stands from which it reaches the spot by IK."""
    try:
        _hold_out(held, out, spot)
    except PlanFailure:  # the other arm, left out by a failed fetch, may be in the way
        with contextlib.suppress(PlanFailure):
            park_arms()
            _hold_out(held, out, spot)
    try:
        _put(held, spot, done)
    except PlanFailure as failure:
        if trip:
            done.trips.append(tuple(trip))
        return [failure]
    done.trips.append((*(trip or ()), held.object_name))
    return []


def _put_alone(held: Held, spot: Spot, done: TableSetting) -> list[Exception]:
    """Put ``held`` (in the hand, the other hand empty) at ``spot``; the failures."""
    try:
        _put(held, spot, done)
    except PlanFailure as failure:
        return [failure]
    done.trips.append((held.object_name,))
    return []


def _deliver_alone(held: Held, spot: Spot, done: TableSetting) -> list[Exception]:
    """Put ``held`` (in the hand as picked up) at ``spot``; the failures."""
    try:
        deliver_to_spot(held, spot, done)
    except PlanFailure as failure:
        return [failure]
    done.placed[held.object_name] = spot
    done.trips.append((held.object_name,))
    return []


def _alone(spot: Spot, visit: Visit, done: TableSetting) -> list[Exception]:
    """Bring the thing of ``spot`` on its own trip; the failures."""
    try:
        bring_one(spot, visit, done)
    except PlanFailure as failure:
        return [failure]
    return []

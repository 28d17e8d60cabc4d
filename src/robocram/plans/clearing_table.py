"""Clearing the table: every thing on it goes back where the KB says it is kept.

CRAM's table-clearing activity, robot-independently. What is on the table is perceived
(the robot stands where it sees the table's middle and detects every thing whose type has
a usual place, ``usual_location/3``), unless the caller names the things. They are
grouped by their usual place; a container is opened before the first thing of its group
is brought back (hands free), each thing is looked at again, fetched from the table and
delivered ``on`` its surface or ``in_`` its container, and the container is closed once
the group is done. A thing that cannot be brought back is recorded and the rest still
are; then :class:`ActivityIncomplete` names what is left, every container closed.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

from robocram.designators import a, all_, an
from robocram.designators.errors import DesignatorError
from robocram.execution import perform, sub_task
from robocram.execution.failures import PlanFailure
from robocram.knowledge.scene_predicates import SEAT, USUAL_LOCATION
from robocram.knowledge.world_predicates import OBJECT_TYPE
from robocram.logic import current_kb
from robocram.plans.activity_failures import ActivityIncomplete
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import look_from_above, navigate, park_arms
from robocram.plans.bringing import Visit, usual_place
from robocram.plans.container_access import is_container
from robocram.plans.deliver import deliver
from robocram.plans.environment_links import environment_link_pose
from robocram.plans.errors import PlanSetupError
from robocram.plans.fetch import fetch
from robocram.plans.pick_object import Held
from robocram.plans.robot_facts import current_robot
from robocram.plans.search import LOOK_ABOVE, Place, search
from robocram.plans.table_arrangement import Table, table_with_seats
from robocram.tf import Pose, PoseStamped, transform_pose
from robocram.tf import quaternion as quat

TABLE_MARGIN = 0.25  # [m] past the farthest seat from the table's middle, still on it
LOOKS = 2  # views of the table the robot takes
MIDDLE_ABOVE = 0.3  # [m] the middle looked at is this far over the table top's frame
SETTING_DEPTH = 0.25  # [m] a place setting's middle, in from the table's edge


@dataclass
class TableClearing:
    """What clearing did: each thing brought back and where to, what it opened (and closed
    again), every attempt."""

    table: Table
    returned: dict[str, Place] = field(default_factory=dict)  # object name -> its place
    opened: list[str] = field(default_factory=list)  # container links, in opening order
    log: AttemptLog = field(default_factory=AttemptLog)


def _on_table(table: Table, point: tuple[float, float, float]) -> bool:
    """Whether ``point`` (map) lies over the table: no farther from its middle than its
    farthest seat plus :data:`TABLE_MARGIN`, and above its top's frame."""
    middle = environment_link_pose(table.environment, table.link, "a table").position
    rows = SEAT.answers(current_kb(), environment=table.environment, link=table.link)
    reach = max((math.hypot(r.x, r.y) for r in rows), default=0.0) + TABLE_MARGIN
    off = math.hypot(point[0] - middle[0], point[1] - middle[1])
    return off <= reach and middle[2] - 0.05 <= point[2] <= middle[2] + 0.5


def look_targets(table: Table) -> list[tuple[float, float, float]]:
    """Points (map) to look at to see what is on ``table``: over its middle (high enough
    to see past a milk carton there), then over each seat's place setting."""
    origin = environment_link_pose(table.environment, table.link, "a table")
    x, y, z = origin.position
    points = [(x, y, z + MIDDLE_ABOVE)]
    for row in SEAT.answers(current_kb(), environment=table.environment, link=table.link):
        inward = origin * Pose((row.x, row.y, 0.0), quat.from_euler(0.0, 0.0, row.yaw))
        sx, sy, sz = (inward * Pose((SETTING_DEPTH, 0.0, 0.0))).position
        points.append((sx, sy, sz + LOOK_ABOVE))
    return points


def things_on(table: Table) -> dict[str, tuple[str, tuple[float, float, float]]]:
    """What the robot sees on ``table``: name -> (type, map point), for every type the KB
    keeps somewhere, from up to :data:`LOOKS` views (a view that cannot be had is skipped)."""
    kinds = sorted({row.type for row in USUAL_LOCATION.answers(current_kb())})
    found: dict[str, tuple[str, tuple[float, float, float]]] = {}
    looks = 0
    for point in look_targets(table):
        with contextlib.suppress(PlanFailure, DesignatorError):
            park_arms()
            navigate(a.location(visible_for=current_robot(), target=point))
            look_from_above(PoseStamped("map", point))
            looks += 1
            for kind in kinds:
                found.update(_seen_of(kind, table))
        if looks >= LOOKS:
            break
    return found


def _seen_of(kind: str, table: Table) -> dict[str, tuple[str, tuple[float, float, float]]]:
    try:
        seen = perform(a.motion(type="detecting", object=all_.objects(type=kind)))
    except PlanFailure:
        return {}
    found = {}
    for thing in seen:
        point = transform_pose(thing.get("pose"), "map").pose.position
        if _on_table(table, point):
            found[str(thing.get("name"))] = (kind, point)
    return found


def _fetch_again(name: str, kind: str, point: tuple[float, float, float], log: AttemptLog) -> Held:
    """Fetch ``name`` from where it was seen (``point``, map: fetching looks there again
    from its stands); where it is gone from there, search for it and fetch it."""
    remembered = an.object(type=kind, name=name, pose=PoseStamped("map", point))
    try:
        return fetch(remembered, log=log)
    except PlanFailure:
        return fetch(search(an.object(type=kind, name=name)), log=log)


def _named(name: str) -> tuple[str, tuple[float, float, float]]:
    """The type and map point of the thing ``name``, from the KB."""
    row = OBJECT_TYPE.first(current_kb(), object=name)
    if row is None:
        raise PlanSetupError(f"no object {name!r} in the world to clear; name things on the table")
    return row.type, transform_pose(PoseStamped(name), "map").pose.position


def back_to(place: Place, name: str) -> object:
    """Where ``name`` goes back to: on its surface, or in its container."""
    where = (place.environment, place.link)
    if is_container(place.environment, place.link):
        return a.location(in_=where, for_=name)
    return a.location(on=where, for_=name)


def _return_group(
    place: Place, things: list[tuple[str, str, tuple[float, float, float]]], done: TableClearing
) -> list[Exception]:
    visit = Visit(place)
    failures: list[Exception] = []
    try:
        visit.open(done.log)
        for name, kind, point in things:
            with sub_task(f"returning {name}"):
                try:
                    held = _fetch_again(name, kind, point, done.log)
                    deliver(held, back_to(place, name), held.arm, log=done.log)
                    done.returned[name] = place
                except PlanFailure as failure:
                    failures.append(failure)
    except PlanFailure as failure:  # the container would not open
        failures.append(failure)
    finally:
        done.opened += [o.container.link for o in visit.opened]
        failures += visit.close(done.log)
    return failures


def clear_table(
    table: Table | tuple[str, str] | None = None, objects: Sequence[str] | None = None
) -> TableClearing:
    """Bring every thing on ``table`` (or the ``objects`` named) back to its usual place.

    Raises:
        ActivityIncomplete: some things could not be brought back (the rest are, and every
            container opened is closed).
    """
    chosen = table_with_seats(table)
    done = TableClearing(chosen)
    seen = things_on(chosen) if objects is None else {n: _named(n) for n in objects}
    groups: dict[Place, list[tuple[str, str, tuple[float, float, float]]]] = {}
    failures: list[Exception] = []
    for name, (kind, point) in seen.items():
        place = usual_place(kind)
        if place is None:
            failures.append(
                PlanSetupError(
                    f"the KB keeps no {kind} anywhere, so {name} has no place to go back to; "
                    f"add usual_location({kind}, Env, Link)"
                )
            )
            continue
        groups.setdefault(place, []).append((name, kind, point))
    for place, things in groups.items():
        with sub_task(f"clearing into {place.link}"):
            failures += _return_group(place, things, done)
    with contextlib.suppress(PlanFailure):
        park_arms()
    if failures:
        left = tuple(n for n in seen if n not in done.returned)
        raise ActivityIncomplete(
            f"brought back {len(done.returned)} of {len(seen)} things; left: {', '.join(left)}",
            activity="clearing-table",
            done=tuple(done.returned),
            missing=left,
            causes=tuple(failures),
        )
    return done

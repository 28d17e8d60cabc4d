"""Clearing the table: every thing on it goes back where the KB says it is kept.

CRAM's table-clearing activity, robot-independently. What is on the table is perceived
(the robot stands where it sees the table's middle and detects every thing whose type has
a usual place, ``usual_location/3``), unless the caller names the things. They are
grouped by their usual place; a container is opened before the first thing of its group
is brought back (hands free), each thing is looked at again, fetched from the table and
delivered ``on`` its surface or ``in_`` its container, and the container is closed once
the group is done. A thing that cannot be brought back is recorded and the rest still
are; one left in the hand is put down on the table first, so the hand is free for them.
What is left on the table is tried again, regrouped by place, once the rest is back (the
milk gone, the cup beside it is free), round after round while a round brings something
back; then :class:`ActivityIncomplete` names what is left, every container closed.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field

from robocram.designators import a, all_, an
from robocram.designators.errors import DesignatorError
from robocram.execution import perform, sub_task
from robocram.execution.failures import PlanFailure
from robocram.knowledge.grasp_predicates import OBJECT_GRASP
from robocram.knowledge.scene_predicates import SEAT, USUAL_LOCATION, USUAL_SPOT
from robocram.knowledge.world_predicates import OBJECT_TYPE
from robocram.logic import current_kb
from robocram.plans.activity_failures import ActivityIncomplete
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import look_from_above, navigate, park_arms
from robocram.plans.bringing import Visit, usual_place
from robocram.plans.container_access import is_container
from robocram.plans.deliver import deliver, holds
from robocram.plans.environment_links import environment_link_pose
from robocram.plans.errors import DeliveryExhausted, PlanSetupError
from robocram.plans.fetch import fetch
from robocram.plans.known_robot import current_robot
from robocram.plans.line_put import line_put
from robocram.plans.location_poses import location_poses
from robocram.plans.pick_object import Held
from robocram.plans.place_object import place_object
from robocram.plans.search import LOOK_ABOVE, Place, search
from robocram.plans.setting_table import SPOT_AREA, SPOT_RESOLUTION
from robocram.plans.stands import map_pose, yaw_of
from robocram.plans.table_arrangement import Table, table_with_seats
from robocram.tf import Pose, PoseStamped, transform_pose
from robocram.tf import quaternion as quat

TABLE_MARGIN = 0.25  # [m] past the farthest seat from the table's middle, still on it
LOOKS = 2  # views of the table the robot takes
MIDDLE_ABOVE = 0.3  # [m] the middle looked at is this far over the table top's frame
SETTING_DEPTH = 0.25  # [m] a place setting's middle, in from the table's edge
SETTING_REACH = 0.3  # [m] things this near a place setting's middle were seen at it
SPOT_TRIES = 2  # cells round a usual spot tried, one stand each, before anywhere in its place
Point = tuple[float, float, float]  # [m] in map


@dataclass
class TableClearing:
    """What clearing did: each thing brought back and where to, what it opened (and closed
    again), every attempt."""

    table: Table
    returned: dict[str, Place] = field(default_factory=dict)  # object name -> its place
    opened: list[str] = field(default_factory=list)  # container links, in opening order
    log: AttemptLog = field(default_factory=AttemptLog)


def _on_table(table: Table, point: Point) -> bool:
    """Whether ``point`` (map) lies over the table: no farther from its middle than its
    farthest seat plus :data:`TABLE_MARGIN`, and above its top's frame."""
    middle = environment_link_pose(table.environment, table.link, "a table").position
    rows = SEAT.answers(current_kb(), environment=table.environment, link=table.link)
    reach = max((math.hypot(r.x, r.y) for r in rows), default=0.0) + TABLE_MARGIN
    off = math.hypot(point[0] - middle[0], point[1] - middle[1])
    return off <= reach and middle[2] - 0.05 <= point[2] <= middle[2] + 0.5


def look_targets(table: Table) -> list[Point]:
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


def things_on(table: Table) -> dict[str, tuple[str, Point]]:
    """What the robot sees on ``table``: name -> (type, map point), for every type the KB
    keeps somewhere, from :data:`LOOKS` views (a view that cannot be had is skipped), and
    more while each view shows things the ones before did not. A place setting where
    things were seen already is not looked at again (an HSR's camera, lower than a PR2's,
    sees the table's middle and the nearer setting, not the other one)."""
    kinds = sorted({row.type for row in USUAL_LOCATION.answers(current_kb())})
    found: dict[str, tuple[str, Point]] = {}
    looks, new = 0, False
    for k, point in enumerate(look_targets(table)):
        if looks >= LOOKS and not new:
            break
        if k > 0 and _seen_near(found, point):
            continue
        with contextlib.suppress(PlanFailure, DesignatorError):
            park_arms()
            navigate(a.location(visible_for=current_robot().name, target=point))
            look_from_above(PoseStamped("map", point))
            looks += 1
            known = len(found)
            for kind in kinds:
                found.update(_seen_of(kind, table))
            new = len(found) > known
    return found


def _seen_near(found: dict[str, tuple[str, Point]], point: Point) -> bool:
    """Whether a thing in ``found`` stands within :data:`SETTING_REACH` of ``point``."""
    return any(
        math.hypot(x - point[0], y - point[1]) <= SETTING_REACH for _, (x, y, _z) in found.values()
    )


def _seen_of(kind: str, table: Table) -> dict[str, tuple[str, Point]]:
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


def _fetch_again(
    name: str,
    kind: str,
    point: Point,
    log: AttemptLog,
    arm: str | None = None,
    grasp: str | None = None,
) -> Held:
    """Fetch ``name`` (with ``arm``, or any; by ``grasp``, or any) from where it was seen
    (``point``, map: fetching looks there again from its stands); where it is gone from
    there, search for it and fetch it."""
    remembered = an.object(type=kind, name=name, pose=PoseStamped("map", point))
    try:
        return fetch(remembered, arm=arm, grasp=grasp, log=log)
    except PlanFailure:
        return fetch(search(an.object(type=kind, name=name)), arm=arm, grasp=grasp, log=log)


def _return_one(name: str, kind: str, point: Point, place: Place, done: TableClearing) -> None:
    """Fetch ``name`` from the table and put it back in ``place``. A hand that holds it so
    that no stand reaches its spot there (a carton past a fridge's open door, held from the
    other side) puts it down again where it was, and the next hand takes it. When the last
    hand could not put it back either, it is taken by the thing's other grasps
    (:func:`_taken_otherwise`).

    Raises:
        PlanFailure: fetching failed, or no hand and no grasp put it back.
    """
    arms = current_robot().arms()
    tried: list[str] = []
    while True:
        was = map_pose(name)
        untried = [arm for arm in arms if arm not in tried]
        held = _fetch_again(name, kind, point, done.log, untried[0] if tried else None)
        tried.append(held.arm)
        if len(tried) >= len(arms) or _reaches_back(held, place, kind):
            break
        deliver(held, was, held.arm, log=done.log)  # from where it stands: the pick undone
    try:
        _deliver_back(held, place, kind, done.log)
    except DeliveryExhausted as failure:
        if not holds(held):
            raise
        _taken_otherwise(held, was, place, kind, done, failure)


def _taken_otherwise(
    held: Held, was: Pose, place: Place, kind: str, done: TableClearing, failure: PlanFailure
) -> None:
    """After every hand took ``held``'s thing by its first grasp and none put it back: put
    it down where it was (``was``, map) and take it by each other grasp the KB has for it,
    any hand, until one puts it back in ``place``. A carton taken from above on a table
    has no room for the hand under a fridge's shelf; taken from the side, it slides in.
    When no other grasp did, it is put down square to the robot (:func:`_squared`) and
    the other grasps are tried once more.

    Raises:
        PlanFailure: the last failure met (``failure``, the first grasp's delivery, if no
            other grasp took it), the thing put down where it was.
    """
    name = held.object_name
    first = held.grasp
    deliver(held, was, held.arm, log=done.log)  # from where it stands: the pick undone
    others = [grasp for grasp in grasps_of(name) if grasp != first]
    last = _by_grasps(name, kind, place, done, others, failure)
    if last is None:
        return
    if not _squared(name, kind, first, done):
        raise last
    last = _by_grasps(name, kind, place, done, [*others, first], last)  # turned now
    if last is not None:
        raise last


def _by_grasps(
    name: str,
    kind: str,
    place: Place,
    done: TableClearing,
    grasps: list[str],
    failure: PlanFailure,
) -> PlanFailure | None:
    """Take ``name`` by each of ``grasps`` in turn, any hand, until one puts it back in
    ``place`` (None); else the last failure met (``failure`` if none was), the thing put
    down again where it lay."""
    for grasp in grasps:
        was = map_pose(name)
        seen = an.object(type=kind, name=name, pose=PoseStamped.from_pose("map", was))
        try:
            again = fetch(seen, grasp=grasp, log=done.log)
        except PlanFailure as missed:  # not by this grasp from any stand: the next one
            failure = missed
            continue
        try:
            _deliver_back(again, place, kind, done.log)
            return None
        except DeliveryExhausted as missed:
            failure = missed
            if holds(again):
                deliver(again, was, again.arm, log=done.log)
    return failure


def _squared(name: str, kind: str, grasp: str, done: TableClearing) -> bool:
    """Whether ``name``, taken again by ``grasp`` (the one that first took it), was put
    down where it lies, square to the robot's base (its sides facing the stand, each
    turn of :data:`place_object.TURNS` tried). A carton put down turned 50 degrees, as the
    hand carried it back from a fridge, offered no stand its side grasps (Boxy, seeded
    households 2, 5 and 9); square, one faces the robot. False: not taken, or not put
    down square (then put down where it lay, as held)."""
    lay = map_pose(name)
    seen = an.object(type=kind, name=name, pose=PoseStamped.from_pose("map", lay))
    try:
        held = fetch(seen, grasp=grasp, log=done.log)
    except PlanFailure:
        return False
    square = quat.from_euler(0.0, 0.0, yaw_of(map_pose(current_robot().base_frame())))
    try:
        place_object(held, PoseStamped.from_pose("map", Pose(lay.position, square)), held.arm)
    except PlanFailure:
        if holds(held):
            deliver(held, lay, held.arm, log=done.log)
        return False
    return True


def grasps_of(name: str) -> list[str]:
    """The names of the KB's grasps of the thing ``name`` by any arm of the robot, as the
    arms rank them (each once)."""
    robot = current_robot()
    names: list[str] = []
    for arm in robot.grasping_arms():
        for row in OBJECT_GRASP.answers(current_kb(), object=name, robot=robot.name, arm=arm):
            if row.grasp not in names:
                names.append(row.grasp)
    return names


def _reaches_back(held: Held, place: Place, kind: str) -> bool:
    """Whether some stand lets ``held.arm`` put the held thing at a free spot in ``place``
    (a ``reachable_for`` location for the spot, as it is held now)."""
    name = held.object_name
    heading = map_pose(name).orientation
    for spot in [*usual_spots(kind, place), None]:
        with contextlib.suppress(DesignatorError, StopIteration):
            where = next(location_poses(back_to(place, name, spot)))
            target = PoseStamped.from_pose("map", Pose(where.position, heading))
            reach = a.location(reachable_for=current_robot().name, target=target, arm=held.arm)
            next(location_poses(reach))
            return True
    return False


def _named(name: str) -> tuple[str, Point]:
    """The type and map point of the thing ``name``, from the KB."""
    row = OBJECT_TYPE.first(current_kb(), object=name)
    if row is None:
        raise PlanSetupError(f"no object {name!r} in the world to clear; name things on the table")
    return row.type, transform_pose(PoseStamped(name), "map").pose.position


def back_to(place: Place, name: str, spot: Point | None = None) -> object:
    """Where ``name`` goes back to: on its surface, or in its container; ``at`` ``spot``
    (map) if given."""
    where = (place.environment, place.link)
    near = {"at": spot, "size": SPOT_AREA, "resolution": SPOT_RESOLUTION} if spot else {}
    if is_container(place.environment, place.link):
        return a.location(in_=where, for_=name, **near)
    return a.location(on=where, for_=name, **near)


def usual_spots(kind: str, place: Place) -> list[Point]:
    """The map points of the KB's ``usual_spot/5`` of ``kind`` in ``place`` (its link as
    it stands now: an opened drawer's spots have moved out with it)."""
    rows = USUAL_SPOT.answers(
        current_kb(), type=kind, environment=place.environment, link=place.link
    )
    frame = environment_link_pose(place.environment, place.link, "a usual place")
    return [(frame * Pose((row.x, row.y, 0.0))).position for row in rows]


def _deliver_back(held: Held, place: Place, kind: str, log: AttemptLog) -> None:
    """Put ``held`` at the first usual spot of its kind in ``place`` that takes it (one
    another thing took fails at once: no free cell), else anywhere in ``place``.

    Raises:
        DeliveryExhausted: not even anywhere in ``place``.
    """
    name = held.object_name
    for spot in usual_spots(kind, place):
        with contextlib.suppress(DeliveryExhausted):  # one stand per spot: then anywhere
            deliver(
                held, back_to(place, name, spot), held.arm, stand_retries=1,
                place_retries=SPOT_TRIES, log=log, reach_stands=True,
            )  # fmt: skip
            return
    try:
        deliver(held, back_to(place, name), held.arm, log=log, reach_stands=True)
    except DeliveryExhausted:
        if not holds(held) or not is_container(place.environment, place.link):
            raise
        frame = environment_link_pose(place.environment, place.link, "a usual place")
        depths = [yaw_of(frame) + k * math.pi / 2 for k in range(4)]  # its level axes
        if line_put(held, _shelf_spots(place, kind, name), depths) is None:
            raise


def _shelf_spots(place: Place, kind: str, name: str) -> Iterator[Pose]:
    """The first pose of each usual spot of ``kind`` in ``place``, then of anywhere in it
    (what the usual puts tried), for a put from a line stand (:func:`line_put`)."""
    for spot in [*usual_spots(kind, place), None]:
        with contextlib.suppress(DesignatorError, StopIteration):
            yield next(location_poses(back_to(place, name, spot)))


def _return_group(
    place: Place, things: list[tuple[str, str, Point]], done: TableClearing
) -> tuple[dict[str, Exception], list[Exception]]:
    """Bring ``things`` back into ``place``, opening it first and closing it after; the
    failure of each thing not brought back (by name: the container's, when it would not
    open), and the container's failures to close.
    A thing still in the hand after its failure is put down on the table
    (:func:`_put_down`): the hand is free for the rest, and a later round may take it."""
    visit = Visit(place)
    missed: dict[str, Exception] = {}
    failures: list[Exception] = []
    try:
        visit.open(done.log)
        for name, kind, point in things:
            with sub_task(f"returning {name}"):
                try:
                    _return_one(name, kind, point, place, done)
                    done.returned[name] = place
                except PlanFailure as failure:
                    missed[name] = failure
                    _put_down(name, done)
    except PlanFailure as failure:  # the container would not open: what is left is missed
        for name, _, _ in things:  # by it (a round that brought nothing back ends clearing)
            if name not in done.returned:
                missed.setdefault(name, failure)
    finally:
        done.opened += [o.container.link for o in visit.opened]
        failures += visit.close(done.log)
    return missed, failures


def _put_down(name: str, done: TableClearing) -> None:
    """Put ``name`` down on the table if a hand still holds it after its return failed
    (the drafted Stretch's cup, whose fingers would open into the milk beside the spot it
    was taken from, stayed in the hand, and every container after it could not be opened:
    seeded household 16). Anywhere on the table that takes it; held still if none does."""
    robot = current_robot()
    holding = robot.held_objects(robot.grasping_arms()).items()
    arm = next((hand for hand, thing in holding if thing == name), None)
    if arm is None:
        return
    table = done.table
    on_table = a.location(on=(table.environment, table.link), for_=name)
    with contextlib.suppress(PlanFailure, DesignatorError):
        deliver(name, on_table, arm, log=done.log, reach_stands=True)


def _still_on_table(name: str, table: Table) -> Point | None:
    """Where ``name`` lies (map) if it lies on ``table`` and no hand holds it."""
    robot = current_robot()
    if name in robot.held_objects(robot.grasping_arms()).values():
        return None
    point = map_pose(name).position
    return point if _on_table(table, point) else None


def _grouped(
    seen: dict[str, tuple[str, Point]], failures: list[Exception]
) -> dict[Place, list[tuple[str, str, Point]]]:
    """``seen`` grouped by each thing's usual place; a thing whose type has none adds a
    failure naming the fix."""
    groups: dict[Place, list[tuple[str, str, Point]]] = {}
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
    return groups


def _round(
    groups: dict[Place, list[tuple[str, str, Point]]], done: TableClearing
) -> tuple[dict[str, Exception], list[Exception]]:
    """One round over ``groups``, place by place; each failed thing's failure (by name)
    and the containers' failures."""
    missed: dict[str, Exception] = {}
    failures: list[Exception] = []
    for place, things in groups.items():
        with sub_task(f"clearing into {place.link}"):
            group_missed, group_failures = _return_group(place, things, done)
        missed.update(group_missed)
        failures += group_failures
    return missed, failures


def clear_table(
    table: Table | tuple[str, str] | None = None, objects: Sequence[str] | None = None
) -> TableClearing:
    """Bring every thing on ``table`` (or the ``objects`` named) back to its usual place;
    what failed and still lies on the table, again after the rest (:func:`_round`).

    Raises:
        ActivityIncomplete: some things could not be brought back (the rest are, and every
            container opened is closed).
    """
    chosen = table_with_seats(table)
    done = TableClearing(chosen)
    seen = things_on(chosen) if objects is None else {n: _named(n) for n in objects}
    failures: list[Exception] = []
    missed, round_failures = _round(_grouped(seen, failures), done)
    failures += round_failures
    while missed:  # what is left, once more while a round brings something back
        again = {n: (seen[n][0], p) for n in missed if (p := _still_on_table(n, chosen))}
        if not again:
            break
        with sub_task("clearing what was left"):
            missed_again, round_failures = _round(_grouped(again, []), done)
        failures += round_failures
        missed = {n: missed_again.get(n, f) for n, f in missed.items() if n not in done.returned}
        if len(missed_again) == len(again):  # nothing came back: no round will do better
            break
    failures += missed.values()
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

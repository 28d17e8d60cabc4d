"""One trip of table setting: find a thing where it is kept, fetch it, put it at its spot.

The result type of setting the table lives here too, so one-armed and two-armed trips
(:mod:`robocram.plans.two_armed_trips`) record what they did in the same place.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from robocram.designators import LocationDesignator, a
from robocram.designators.errors import GroundingError
from robocram.execution.failures import PlanFailure
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.bringing import Visit, find, wanted_object
from robocram.plans.deliver import deliver
from robocram.plans.errors import DeliveryExhausted
from robocram.plans.fetch import fetch
from robocram.plans.pick_object import Held
from robocram.plans.table_arrangement import Spot, Table

SPOT_AREA = 0.3  # [m] side of the square searched round a spot
SPOT_RESOLUTION = 0.01  # [m] cells of that square: a spot is met within about a cell
WIDE_SPOT_AREA = 0.5  # [m] the square, where the first had no cell at all: a thing held
# turned has wider bounds, and their half diagonal plus the margin kept free round it no
# longer fits in half of :data:`SPOT_AREA` (the square's edge counts as taken)


@dataclass
class TableSetting:
    """What setting the table did: each thing put and its spot, what it opened (and closed
    again), the things found away from their usual place, every attempt, and the things
    each trip to the table carried (two, when two arms carried them together)."""

    table: Table
    placed: dict[str, Spot] = field(default_factory=dict)  # object name -> its spot
    opened: list[str] = field(default_factory=list)  # container links, in opening order
    searched: list[str] = field(default_factory=list)  # objects found by a search elsewhere
    log: AttemptLog = field(default_factory=AttemptLog)
    trips: list[tuple[str, ...]] = field(default_factory=list)  # things put, per trip
    unfetched: list[str] = field(default_factory=list)  # things a free hand's fetch ran
    # dry on: seen again, they are taken only where no other of their kind is seen


def spot_location(
    table: Table,
    spot: Spot,
    name: str,
    see_through: Sequence[str] = (),
    size: float = SPOT_AREA,
) -> LocationDesignator:
    """Where ``name`` goes: on the table, at ``spot`` (a fine costmap round it, ``size`` [m]
    a side); the rays look past the bodies ``see_through`` names (the robot, when it holds
    a second thing)."""
    keys: dict[str, object] = {"see_through": tuple(see_through)} if see_through else {}
    return a.location(
        on=(table.environment, table.link),
        for_=name,
        at=spot.pose.position,
        size=size,
        resolution=SPOT_RESOLUTION,
        **keys,
    )


def no_cell(failure: DeliveryExhausted) -> bool:
    """Whether ``failure`` met nothing but spots the location could not find: its costmap
    had no cell, and no stand was tried."""
    causes = failure.causes or ()
    return bool(causes) and all(isinstance(c, GroundingError) for c in causes)


def deliver_at_spot(
    held: Held,
    spot: Spot,
    done: TableSetting,
    see_through: Sequence[str] = (),
    reach_stands: bool = False,
    where: LocationDesignator | None = None,
) -> None:
    """Put ``held`` at ``spot`` (the table seen past ``see_through``; ``where``: a spot's
    location already tried, whose stream goes on), in the square of :data:`WIDE_SPOT_AREA`
    where the first had no cell at all: a thing held turned needs more room round its
    spot (Boxy's bowl held 16 degrees turned)."""
    if where is None:
        where = spot_location(done.table, spot, held.object_name, see_through)
    try:
        deliver(held, where, held.arm, log=done.log, reach_stands=reach_stands)
    except DeliveryExhausted as failure:
        if not no_cell(failure):
            raise
        wide = spot_location(done.table, spot, held.object_name, see_through, WIDE_SPOT_AREA)
        deliver(held, wide, held.arm, log=done.log, reach_stands=reach_stands)


def deliver_to_spot(held: Held, spot: Spot, done: TableSetting) -> None:
    """Put ``held`` at ``spot`` from the stands that hold it over the spot as the arm
    holds it now; where none did, again, then from those the arm reaches the spot from by
    IK: Boxy's bowl, taken by its rim nearer its drawer's middle, hangs in front of its
    chest when carried, and every stand holding it so over the table put the other,
    parked hand into the table."""
    where = spot_location(done.table, spot, held.object_name)
    try:
        deliver_at_spot(held, spot, done, where=where)
    except DeliveryExhausted:  # the same location: its poses go on from the last tried
        deliver_at_spot(held, spot, done, reach_stands=True, where=where)


def fetch_one(kind: str, visit: Visit, done: TableSetting) -> Held:
    """Find a thing of ``kind`` not yet on the table and fetch it, a free hand; one that
    could not be fetched is remembered, and the next trip takes another of its kind
    where one is seen (the HSR's seed 9 tried bowl-2 twice and never bowl-1).

    Raises:
        PlanFailure: none was found, or fetching failed.
    """
    seen, inside = find(
        wanted_object(kind), visit, done.log, skip=done.placed, later=done.unfetched
    )
    try:
        return fetch(seen, log=done.log, opened=inside)
    except PlanFailure:
        name = str(seen.get("name"))
        if name not in done.unfetched:
            done.unfetched.append(name)
        raise


def bring_one(spot: Spot, visit: Visit, done: TableSetting) -> Held:
    """Find a thing of the spot's type not yet on the table, fetch it, put it at the spot."""
    held = fetch_one(spot.type, visit, done)
    deliver_to_spot(held, spot, done)
    done.placed[held.object_name] = spot
    done.trips.append((held.object_name,))
    return held

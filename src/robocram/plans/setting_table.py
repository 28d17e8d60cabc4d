"""Setting the table: a place setting per person and the shared things, from where they are kept.

CRAM's table-setting activity, robot-independently. The spots come from the table's seat
facts and the arrangement (:mod:`robocram.plans.table_arrangement`); the things are
grouped by where the KB says their type is kept, so a drawer or the fridge is opened once
for everything it holds and closed again before the next place. Each thing is found
(looked for in its place, else searched for everywhere), fetched and delivered to a
location ``on`` the table ``at`` its spot (costmaps give the height and check the spot is
free). A thing that cannot be brought is recorded and the rest of the table is still set;
then :class:`ActivityIncomplete` names what is missing, every container closed.
"""

from __future__ import annotations

import contextlib
from collections.abc import Sequence
from dataclasses import dataclass, field

from robocram.designators import LocationDesignator, a
from robocram.execution import sub_task
from robocram.execution.failures import PlanFailure
from robocram.plans.activity_failures import ActivityIncomplete
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import park_arms
from robocram.plans.bringing import Visit, find, usual_place, wanted_object
from robocram.plans.deliver import deliver
from robocram.plans.fetch import fetch
from robocram.plans.pick_object import Held
from robocram.plans.search import Place
from robocram.plans.table_arrangement import (
    SHARED,
    STANDARD_SETTING,
    Setting,
    Spot,
    Table,
    spots,
    table_with_seats,
)

SPOT_AREA = 0.3  # [m] side of the square searched round a spot
SPOT_RESOLUTION = 0.01  # [m] cells of that square: a spot is met within about a cell


@dataclass
class TableSetting:
    """What setting the table did: each thing put and its spot, what it opened (and closed
    again), the things found away from their usual place, every attempt."""

    table: Table
    placed: dict[str, Spot] = field(default_factory=dict)  # object name -> its spot
    opened: list[str] = field(default_factory=list)  # container links, in opening order
    searched: list[str] = field(default_factory=list)  # objects found by a search elsewhere
    log: AttemptLog = field(default_factory=AttemptLog)


def spot_location(table: Table, spot: Spot, name: str) -> LocationDesignator:
    """Where ``name`` goes: on the table, at ``spot`` (a fine costmap round it)."""
    return a.location(
        on=(table.environment, table.link),
        for_=name,
        at=spot.pose.position,
        size=SPOT_AREA,
        resolution=SPOT_RESOLUTION,
    )


def by_place(wanted: Sequence[Spot]) -> list[tuple[Place | None, list[Spot]]]:
    """The spots grouped by the place their type is kept, places in first-asked order."""
    groups: dict[Place | None, list[Spot]] = {}
    for spot in wanted:
        groups.setdefault(usual_place(spot.type), []).append(spot)
    return list(groups.items())


def _bring(spot: Spot, visit: Visit, done: TableSetting) -> Held:
    """Find a thing of the spot's type not yet on the table, fetch it, put it at the spot."""
    seen, inside = find(wanted_object(spot.type), visit, done.log, skip=done.placed)
    held = fetch(seen, log=done.log, opened=inside)
    deliver(held, spot_location(done.table, spot, held.object_name), held.arm, log=done.log)
    done.placed[held.object_name] = spot
    return held


def _serve(place: Place | None, group: list[Spot], done: TableSetting) -> list[Exception]:
    """Bring every spot's thing of one place, then close what was opened; the failures."""
    visit = Visit(place)
    failures: list[Exception] = []
    try:
        for spot in group:
            with sub_task(f"bringing {spot.type}"):
                try:
                    _bring(spot, visit, done)
                except PlanFailure as failure:
                    failures.append(failure)
    finally:
        done.opened += [o.container.link for o in visit.opened]
        done.searched += visit.searched
        failures += visit.close(done.log)
    return failures


def set_table(
    people: int = 2,
    table: Table | tuple[str, str] | None = None,
    setting: Sequence[Setting] = STANDARD_SETTING,
    shared: Sequence[str] = SHARED,
) -> TableSetting:
    """Set ``table`` (default: the KB's table with seats) for ``people``; what was done.

    Raises:
        PlanSetupError: fewer seats than people, or no table with seats.
        ActivityIncomplete: some things could not be brought (the rest are set, and
            every container opened is closed).
    """
    chosen = table_with_seats(table)
    wanted = spots(chosen, people, setting, shared)
    done = TableSetting(chosen)
    failures: list[Exception] = []
    for place, group in by_place(wanted):
        with sub_task(f"setting from {place.link if place else 'anywhere'}"):
            failures += _serve(place, group, done)
    with contextlib.suppress(PlanFailure):
        park_arms()
    if failures:
        missing = len(wanted) - len(done.placed)
        raise ActivityIncomplete(
            f"set {len(done.placed)} of {len(wanted)} things for {people}; "
            f"{missing} missing: " + "; ".join(type(f).__name__ for f in failures),
            activity="setting-table",
            done=tuple(done.placed),
            missing=tuple(s.type for s in wanted if s not in done.placed.values()),
            causes=tuple(failures),
        )
    return done

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

from robocram.execution import sub_task
from robocram.execution.failures import PlanFailure
from robocram.plans.activity_failures import ActivityIncomplete
from robocram.plans.basic_actions import park_arms
from robocram.plans.bringing import Visit, usual_place
from robocram.plans.known_robot import current_robot
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
from robocram.plans.table_trips import (
    SPOT_AREA,
    SPOT_RESOLUTION,
    TableSetting,
    bring_one,
    spot_location,
)
from robocram.plans.two_armed_trips import bring_two

__all__ = ["SPOT_AREA", "SPOT_RESOLUTION", "TableSetting", "set_table", "spot_location"]


def by_place(wanted: Sequence[Spot]) -> list[tuple[Place | None, list[Spot]]]:
    """The spots grouped by the place their type is kept, places in first-asked order."""
    groups: dict[Place | None, list[Spot]] = {}
    for spot in wanted:
        groups.setdefault(usual_place(spot.type), []).append(spot)
    return list(groups.items())


def trips(group: list[Spot], two_arms: bool) -> list[list[Spot]]:
    """The spots of one place, by the trip that brings their things: two by two with
    ``two_arms`` (an odd one last, alone), else one by one."""
    size = 2 if two_arms else 1
    return [group[i : i + size] for i in range(0, len(group), size)]


def _serve(
    place: Place | None, group: list[Spot], done: TableSetting, two_arms: bool = False
) -> list[Exception]:
    """Bring every spot's thing of one place, then close what was opened; the failures."""
    visit = Visit(place)
    failures: list[Exception] = []
    try:
        for trip in trips(group, two_arms):
            with sub_task(f"bringing {' and '.join(spot.type for spot in trip)}"):
                if len(trip) == 2:
                    failures += bring_two(trip[0], trip[1], visit, done)
                    continue
                try:
                    bring_one(trip[0], visit, done)
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
    two_arms: bool = True,
) -> TableSetting:
    """Set ``table`` (default: the KB's table with seats) for ``people``; what was done.

    ``two_arms`` (default): a robot with two arms carries two things of one place per
    trip where it can (:mod:`robocram.plans.two_armed_trips`); False brings one thing per
    trip. A robot with one arm ignores it.

    Raises:
        PlanSetupError: fewer seats than people, or no table with seats.
        ActivityIncomplete: some things could not be brought (the rest are set, and
            every container opened is closed).
    """
    chosen = table_with_seats(table)
    wanted = spots(chosen, people, setting, shared)
    done = TableSetting(chosen)
    failures: list[Exception] = []
    pairs = two_arms and len(current_robot().grasping_arms()) >= 2
    for place, group in by_place(wanted):
        with sub_task(f"setting from {place.link if place else 'anywhere'}"):
            failures += _serve(place, group, done, pairs)
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

"""Bringing things from where they are kept, for activities that move many things.

An activity groups what it moves by the place the KB says each type is kept
(``usual_location/3``), so a drawer or the fridge is opened once for all the things it
holds and closed again when the group is done (:class:`Visit`). Each thing is looked for
in its place first: in an opened container from in front of it, looking into it, as the
search does; when it is not there, :func:`~robocram.plans.search.search` looks everywhere
else (and opens what it must), and a thing found nowhere raises ``SearchExhausted``.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Collection
from dataclasses import dataclass, field

from robocram.designators import ObjectDesignator, a, all_, an
from robocram.execution import perform
from robocram.execution.failures import NavigationLowLevelFailure, PlanFailure
from robocram.knowledge.scene_predicates import USUAL_LOCATION
from robocram.logic import current_kb
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import detect, look_from_above, navigate, park_arms
from robocram.plans.container_access import (
    OpenedContainer,
    close_again,
    front_in_map,
    is_container,
    is_drawer,
    open_from_front,
)
from robocram.plans.environment_links import environment_link_pose
from robocram.plans.peering import peer_into
from robocram.plans.search import Place, SearchLog, place_point, search
from robocram.tf import PoseStamped

CABINET_DEPTH = 0.25  # [m] behind a door's front, where a robot looks into its cabinet


def usual_place(object_type: str) -> Place | None:
    """The first place the KB says ``object_type`` is kept, if any."""
    row = USUAL_LOCATION.first(current_kb(), type=object_type)
    return Place(row.environment, row.link) if row is not None else None


@dataclass
class Visit:
    """A place an activity takes things from or puts things into, and what it opened."""

    place: Place | None
    opened: list[OpenedContainer] = field(default_factory=list)
    searched: list[str] = field(default_factory=list)  # things found away from the place

    @property
    def container(self) -> OpenedContainer | None:
        """The place itself, if it is a container the visit opened."""
        if self.place is None:
            return None
        return next((o for o in self.opened if o.container.link == self.place.link), None)

    def open(self, log: AttemptLog) -> OpenedContainer | None:
        """Open the place if it is a closed container; the container (None: no container)."""
        place = self.place
        if place is None or not is_container(place.environment, place.link):
            return None
        if self.container is None:
            self.opened.append(open_from_front(place.link, log))
        return self.container

    def close(self, log: AttemptLog) -> list[Exception]:
        """Close what the visit opened, last first; the failures (each is tried)."""
        failures: list[Exception] = []
        for opened in reversed(self.opened):
            try:
                close_again(opened, log)
            except PlanFailure as failure:
                failures.append(failure)
        self.opened.clear()
        with contextlib.suppress(PlanFailure):
            park_arms()
        return failures


def inside_point(opened: OpenedContainer) -> PoseStamped:
    """Where to look into an opened container: a drawer's middle (half its travel behind
    its front now); a door's cabinet :data:`CABINET_DEPTH` behind its front, at its handle's
    height (a fridge's shelves are at the height a hand opens it, not at its floor)."""
    part = opened.container
    now = place_point(Place(part.environment, part.link))
    yaw = front_in_map(part)
    if yaw is None:
        return now
    x, y, z = now.position
    if is_drawer(part):
        back = part.opened / 2
    else:
        back = CABINET_DEPTH
        z = environment_link_pose(part.environment, part.handle, "a handle").position[2]
    return PoseStamped("map", (x - back * math.cos(yaw), y - back * math.sin(yaw), z))


def _look_into(
    opened: OpenedContainer,
    wanted: ObjectDesignator,
    skip: Collection[str],
    move: bool = True,
    later: Collection[str] = (),
) -> ObjectDesignator | None:
    """Stand where ``opened`` was opened from (unless not ``move``: from where the robot
    stands), look into it, detect ``wanted`` there (the first seen that is not in
    ``skip``: a spoon already on the table may be in view; those in ``later`` last). Not
    seen from the opening stand, the robot peers in, lower, closer and farther back
    (:func:`peer_into`)."""
    point = inside_point(opened)
    try:
        park_arms()
        if move:
            _to_opening_stand(opened)
        look_from_above(point)
    except PlanFailure:
        return None
    seen = _seen(wanted, skip, later)
    if seen is None and move:
        seen = peer_into(opened, point, lambda: _seen(wanted, skip, later))
    return seen


def _to_opening_stand(opened: OpenedContainer) -> None:
    """Drive to where ``opened`` was opened from; where what it opened is in the way
    there now (a door swung open towards a Boxy's wide base), to where the base stood
    when it was open.

    Raises:
        NavigationLowLevelFailure: neither can be driven to.
    """
    try:
        navigate(opened.stand.pose)
    except NavigationLowLevelFailure:
        if opened.reached is None:
            raise
        navigate(opened.reached)


def _seen(
    wanted: ObjectDesignator, skip: Collection[str], later: Collection[str] = ()
) -> ObjectDesignator | None:
    """``wanted`` as the robot sees it now, the first not in ``skip``, those in ``later``
    only where no other is seen; None if not seen."""
    try:
        if wanted.get("name") is not None:
            return detect(wanted)
        seen = perform(a.motion(type="detecting", object=all_.objects(type=wanted.get("type"))))
    except PlanFailure:
        return None
    takes = [thing for thing in seen if str(thing.get("name")) not in skip]
    first = [thing for thing in takes if str(thing.get("name")) not in later]
    return next(iter(first or takes), None)


def find_in_place(
    wanted: ObjectDesignator,
    visit: Visit,
    log: AttemptLog,
    skip: Collection[str] = (),
    from_here: bool = False,
    later: Collection[str] = (),
) -> tuple[ObjectDesignator, OpenedContainer] | None:
    """``wanted`` seen in the visit's place, a container opened once, and the container;
    None when it is not a container, cannot be opened or ``wanted`` is not seen there.
    ``from_here``: look from where the robot stands first (it just took a thing there).
    ``later``: things taken only where no other is seen (a fetch ran dry on them)."""
    with contextlib.suppress(PlanFailure):
        inside = visit.open(log)
        if inside is not None:
            seen = _look_into(inside, wanted, skip, False, later) if from_here else None
            seen = seen or _look_into(inside, wanted, skip, later=later)
            if seen is not None:
                return seen, inside
    return None


def find(
    wanted: ObjectDesignator,
    visit: Visit,
    log: AttemptLog,
    skip: Collection[str] = (),
    later: Collection[str] = (),
) -> tuple[ObjectDesignator, OpenedContainer | None]:
    """Find ``wanted`` at its place (opening it once), else anywhere; the perceived object
    and the opened container it lies in. Things named in ``skip`` (already brought) are
    not taken for it where it is kept, those in ``later`` only where no other is seen.

    Raises:
        SearchExhausted: it is nowhere the search looked.
    """
    found = find_in_place(wanted, visit, log, skip, later=later)
    if found is not None:
        return found
    searched = SearchLog(attempts=log)
    try:
        seen = search(wanted, log=searched)
    finally:
        known = {o.container.link for o in visit.opened}
        visit.opened += [o for o in searched.opened if o.container.link not in known]
    visit.searched.append(str(seen.get("name")))
    last = searched.searched[-1] if searched.searched else None
    lies_in = next((o for o in visit.opened if last and o.container.link == last.link), None)
    return seen, lies_in


def wanted_object(object_type: str, name: str | None = None) -> ObjectDesignator:
    """An object designator of ``object_type`` (and ``name``, when one thing is meant)."""
    return an.object(type=object_type, name=name) if name else an.object(type=object_type)

"""Transporting: search for the object, fetch it, deliver it, close what was opened.

The object is searched for only if the robot does not already see it at its usual place.

CRAM's transport plan, robot-independently: the search opens a container when the KB
says the object is usually inside one; fetching and delivering each retry with the next
solution of their location designators, within their bounds; the containers opened are
closed again once the object is delivered, and the arms are parked. Every attempt is in
the :class:`AttemptLog`, so callers (and tests) see what it took. A legged robot that
fetches nothing standing from the container the search opened fetches it again crouched
(:mod:`~robocram.plans.crouching`), standing up before it drives to deliver it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from robocram.designators import ObjectDesignator, an
from robocram.execution import sub_task
from robocram.execution.failures import (
    PerceptionObjectNotFound,
    PlanFailure,
    TorsoLowLevelFailure,
)
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import park_arms
from robocram.plans.container_access import OpenedContainer, close_again, is_container
from robocram.plans.crouching import DEPTHS, can_crouch, crouched
from robocram.plans.deliver import PLACE_RETRIES, deliver
from robocram.plans.deliver import STAND_RETRIES as PLACING_STANDS
from robocram.plans.errors import FetchExhausted
from robocram.plans.fetch import STAND_RETRIES, fetch
from robocram.plans.known_robot import current_robot
from robocram.plans.pick_object import Held
from robocram.plans.place_looks import look_and_detect
from robocram.plans.search import (
    POSES_PER_PLACE,
    SearchLog,
    candidate_places,
    place_point,
    search,
)
from robocram.tf import Pose, transform_pose


@dataclass
class TransportResult:
    """What a transport did: the object, how it was held, where it went, its attempts."""

    object_name: str
    held: Held
    spot: Pose  # [m] where the object was put down, in map
    search: SearchLog = field(default_factory=SearchLog)
    log: AttemptLog = field(default_factory=AttemptLog)

    @property
    def opened(self) -> list[OpenedContainer]:
        """The containers the search opened (closed again by the transport)."""
        return self.search.opened


def _container_it_was_in(searched: SearchLog) -> OpenedContainer | None:
    """The container the search opened where it found the object, if it found it in one."""
    if searched.opened and searched.searched:
        last = searched.opened[-1]
        if last.container.link == searched.searched[-1].link:
            return last
    return None


def _fetch_crouched(
    seen: ObjectDesignator,
    arm: str | None,
    grasp: str | None,
    stand_retries: int,
    log: AttemptLog,
    inside: OpenedContainer,
    standing: FetchExhausted,
) -> Held:
    """Fetch ``seen`` (its pose in the map: kept in the base's frame, it would sink with
    the body) from ``inside`` crouched, at each of the depths in turn, standing up after;
    the last failure raised (``standing`` where no crouch bent)."""
    last: PlanFailure = standing
    for depth in DEPTHS:
        try:
            park_arms()  # a failed pick may leave a hand out over the thing
            with crouched(depth):
                return fetch(seen, arm, grasp, stand_retries, log, opened=inside)
        except PlanFailure as failure:  # no fetch, or the way down blocked where it stood
            last = failure if not isinstance(failure, TorsoLowLevelFailure) else last
    raise last


def _in_map(seen: ObjectDesignator) -> ObjectDesignator:
    """``seen`` with its pose in the map (as it is now), if it has one."""
    pose = seen.get("pose")
    if pose is None:
        return seen
    return seen.make_effective(seen.data or pose, pose=transform_pose(pose, "map"))


def seen_from_here(object: ObjectDesignator | str) -> ObjectDesignator | None:  # noqa: A002
    """The object, if the robot sees it at its usual place without moving; else None.

    A robot that already sees the object does not walk to a place to look at it; a usual
    place that is a container needs opening, so it is left to the search.
    """
    wanted = object if isinstance(object, ObjectDesignator) else an.object(type=object)
    places = candidate_places(str(wanted.get("type")))
    if not places or is_container(places[0].environment, places[0].link):
        return None
    place = (places[0].environment, places[0].link)
    try:
        return look_and_detect(wanted, place_point(places[0]), place, current_robot().base_frame())
    except PerceptionObjectNotFound:
        return None


def transport(
    object: ObjectDesignator | str,  # noqa: A002 - CRAM's key
    target: object,
    arm: str | None = None,
    grasp: str | None = None,
    stand_retries: int = STAND_RETRIES,
    place_retries: int = PLACE_RETRIES,
    placing_stands: int = PLACING_STANDS,
    poses_per_place: int = POSES_PER_PLACE,
    log: AttemptLog | None = None,
) -> TransportResult:
    """Search the object, fetch it, deliver it to ``target``, close what was opened, park.

    Raises:
        SearchExhausted: the object is in no candidate place (PerceptionObjectNotFound).
        FetchExhausted: it was seen but no stand let the robot pick it up.
        DeliveryExhausted: it was held but could not be put down at ``target``.
    """
    log = log if log is not None else AttemptLog()
    searched = SearchLog(attempts=log)
    with sub_task("searching"):
        seen = seen_from_here(object) or search(
            object, poses_per_place=poses_per_place, log=searched
        )
    with sub_task("fetching"):
        inside = _container_it_was_in(searched)
        in_map = _in_map(seen)  # before the base moves: the pose is in its frame
        try:
            held = fetch(seen, arm, grasp, stand_retries, log, opened=inside)
        except FetchExhausted as failure:
            if inside is None or not can_crouch():
                raise
            held = _fetch_crouched(in_map, arm, grasp, stand_retries, log, inside, failure)
    with sub_task("delivering"):
        # reach stands after the held ones: an arm holding the thing at the spot's side
        # may not lower it there (its joint limits), and nearer stands meet the table
        spot = deliver(
            held, target, held.arm, placing_stands, place_retries, log, reach_stands=True
        )
    with sub_task("closing"):
        for opened in reversed(searched.opened):
            close_again(opened, log)
        park_arms()
    return TransportResult(held.object_name, held, spot, searched, log)

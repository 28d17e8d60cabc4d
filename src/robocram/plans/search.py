"""Searching for an object: go where each candidate place is visible, look, detect.

The candidate places come from the knowledge base: first the object type's usual places
(``usual_location(Type, Env, Link)``), then every other supporting surface
(``supporting_surface(Env, Link)``). A place the KB names a container (a drawer, a door)
is opened first, as CRAM does, and looked into from where it was opened, at the middle of
what opening pulled out (a drawer's frame sits at its front: looking there cut the inside
off; a head stopped at its tilt limit with that middle still in view has looked); if
the object is not seen from there (a camera too low to see over the drawer's front, as
Stretch's without a torso), from where that middle is visible, and then from
such stands near the container (``near``: over its rim from close by, not grazing it from
afar). The containers opened are in the log, so a caller closes them again. For each
place the plan asks for a
location from which the robot sees it (``visible_for``, a location designator resolved by whatever
resolver the environment has, e.g. costmaps), tries up to ``poses_per_place`` of its
solutions, looks and detects. When every place is exhausted it raises
:class:`SearchExhausted`, a ``PerceptionObjectNotFound`` that lists the places searched
and names what hid a place or the object (``occluded_by``), when anything did.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from robocram.designators import LocationDesignator, ObjectDesignator, a, an
from robocram.designators.errors import DesignatorError
from robocram.execution import perform
from robocram.execution.failures import PlanFailure, PtuGoalNotReached, failure_line
from robocram.knowledge.robot_predicates import ARM_JOINTS, CAMERA_MAXIMAL_HEIGHT
from robocram.knowledge.scene_predicates import SUPPORTING_SURFACE, USUAL_LOCATION
from robocram.logic import current_kb
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import detect, look_from_above, park_arms
from robocram.plans.container_access import OpenedContainer, is_container, open_from_front
from robocram.plans.culprits import blamed, culprit_clause
from robocram.plans.environment_links import environment_link_pose
from robocram.plans.errors import SearchExhausted
from robocram.plans.known_robot import KnownRobot, current_robot
from robocram.plans.place_looks import look_and_detect
from robocram.plans.stands import map_pose
from robocram.plans.tilt_limit_look import in_view_at_tilt_limit
from robocram.tf import PoseStamped

POSES_PER_PLACE = 2  # CRAM retries a search location a couple of times
LOOK_ABOVE = 0.10  # [m] the point looked at is this far above a place's link frame


@dataclass(frozen=True)
class Place:
    """A link of an environment where objects may be."""

    environment: str
    link: str


@dataclass
class SearchLog:
    """What the search did: the places looked at, the failures met, the containers opened."""

    searched: list[Place] = field(default_factory=list)
    failures: list[PlanFailure | DesignatorError] = field(default_factory=list)
    opened: list[OpenedContainer] = field(default_factory=list)
    attempts: AttemptLog = field(default_factory=AttemptLog)
    shut: list[tuple[Place, PlanFailure]] = field(default_factory=list)  # not opened, why


def candidate_places(object_type: str) -> list[Place]:
    """The usual places of ``object_type`` first, then every other supporting surface."""
    kb = current_kb()
    usual = [Place(r.environment, r.link) for r in USUAL_LOCATION.answers(kb, type=object_type)]
    others = [Place(r.environment, r.link) for r in SUPPORTING_SURFACE.answers(kb)]
    return list(dict.fromkeys([*usual, *others]))


def place_point(place: Place) -> PoseStamped:
    """The point a robot looks at to see ``place``: a little above its link frame (map)."""
    pose = environment_link_pose(place.environment, place.link, "a place")
    x, y, z = pose.position
    return PoseStamped("map", (x, y, z + LOOK_ABOVE))


def camera_below(robot: KnownRobot, places: list[Place]) -> str:
    """A clause saying that the robot's camera, at its highest, is lower than every place in
    ``places`` (their link frames), so it cannot see onto them; empty otherwise, and for a
    camera a neck arm moves. Alex's head, 0.71 m up, searched counters 0.83 m high and
    said only that it saw no mug. The heights are the base frame's (over the floor when it
    lies on it); Centauro's pelvis, its base frame, stands 1.03 m up: its camera 1.58 m up
    was said to be 0.55 m up, below the drawers it had failed to open."""
    kb = current_kb()
    base_z = map_pose(robot.base_frame()).position[2]
    heights = [base_z + f.height for f in CAMERA_MAXIMAL_HEIGHT.answers(kb, robot=robot.name)]
    moved = {row.arm for row in ARM_JOINTS.answers(kb, robot=robot.name)} - set(robot.arms())
    if not heights or not places or moved or min(heights) <= base_z:
        return ""  # none, or an arm carries the camera (the Donbot's wrist): it rises with it
    frames = [environment_link_pose(p.environment, p.link, "a place") for p in places]
    lowest = min(frame.position[2] for frame in frames)
    if max(heights) >= lowest:
        return ""
    return (
        f" (its camera, {max(heights):.2f} m up at most, is below them all, from "
        f"{lowest:.2f} m: mount it higher or add a torso)"
    )


def _stayed_shut(log: SearchLog) -> str:
    """A clause naming the containers the search could not open, with the first one's
    failure: Armar6 searched every counter for the bowl and said only that it saw none,
    while its drawer had stayed shut (its palm on the handle met the counter's top)."""
    if not log.shut:
        return ""
    links = ", ".join(dict.fromkeys(place.link for place, _ in log.shut))
    failure = log.shut[0][1]
    return f" ({links} stayed shut: {failure_line(type(failure).__name__, str(failure))})"


def _look_from_places(
    robot: KnownRobot,
    target: PoseStamped,
    wanted: ObjectDesignator,
    poses: int,
    log: SearchLog,
    near: Place | None = None,
    place: Place | None = None,
) -> ObjectDesignator | None:
    """Look for ``wanted`` from up to ``poses`` stands that see ``target``; with ``near``,
    from stands near that place (an opened container is seen into over its rim from close
    by: from a metre away an HSR's camera grazed a drawer's side and saw 67 % of the bowl
    in it; from right beside a cabinet a PR2's camera, higher, missed a bowl under the
    counter top's edge, so these come after the others). With ``place``, a look the
    camera cannot have at ``target`` is had round it on that place
    (:func:`~robocram.plans.place_looks.look_and_detect`)."""
    keys = {"near": (near.environment, near.link)} if near is not None else {}
    around = (place.environment, place.link) if place is not None else None
    stand = a.location(visible_for=robot.name, target=target.position, **keys)
    for _ in range(poses):
        try:
            perform(a.motion(type="going", target=stand))
            return look_and_detect(wanted, target, around, robot.base_frame())
        except (PlanFailure, DesignatorError) as failure:
            log.failures.append(failure)
            if isinstance(failure, DesignatorError):
                return None  # no (more) location to see the place from
        try:
            following = stand.next_solution()
        except DesignatorError as failure:  # the stream ran dry: no more stands
            log.failures.append(failure)
            return None
        if not isinstance(following, LocationDesignator):
            return None
        stand = following
    return None


def _look_into(
    place: Place, wanted: ObjectDesignator, log: SearchLog
) -> tuple[ObjectDesignator | None, PoseStamped]:
    """Open the container ``place`` and look into it from where it was opened; the object
    seen (or None) and the point looked at: the middle of what opening pulled out."""
    closed = place_point(place)
    inside = closed
    try:
        opened = open_from_front(place.link, log.attempts)
    except PlanFailure as failure:
        log.failures.append(failure)
        log.shut.append((place, failure))
        return None, inside
    try:
        log.opened.append(opened)
        inside = _pulled_out_middle(closed, place_point(place))
        look_into_opened(inside)  # over the drawer's front, into it
        return detect(wanted), inside
    except PlanFailure as failure:
        log.failures.append(failure)
        return None, inside


def look_into_opened(point: PoseStamped) -> None:
    """Look at ``point``, in a container just opened, from above (``look_from_above``); a
    head stopped at its tilt limit with ``point`` still in the view has looked into it
    (:func:`in_view_at_tilt_limit`): TALOS, from where it opened the bowl's drawer, needs
    1.12 rad of its 0.785 and, not looking, sought the bowl elsewhere, saw it in the drawer
    from 1.7 m away and fetched it as if it lay on the counter it had looked at.

    Raises:
        PtuGoalNotReached: the head stopped short of the point with it out of the view.
    """
    try:
        look_from_above(point)
    except PtuGoalNotReached as failure:
        if not in_view_at_tilt_limit(failure):
            raise


def _pulled_out_middle(closed: PoseStamped, opened: PoseStamped) -> PoseStamped:
    """The middle between a container's point closed and opened: of what opening exposed."""
    (cx, cy, cz), (ox, oy, oz) = closed.position, opened.position
    return PoseStamped("map", ((cx + ox) / 2, (cy + oy) / 2, (cz + oz) / 2))


def search(
    object: ObjectDesignator | str,  # noqa: A002 - CRAM's key
    poses_per_place: int = POSES_PER_PLACE,
    log: SearchLog | None = None,
    open_containers: bool = True,
) -> ObjectDesignator:
    """Find the object (a designator with a ``type``, or a type); the perceived designator.

    Raises:
        SearchExhausted: no candidate place shows the object.
    """
    robot = current_robot()
    log = log if log is not None else SearchLog()
    wanted = object if isinstance(object, ObjectDesignator) else an.object(type=object)
    object_type = str(wanted.get("type"))
    park_arms()
    for place in candidate_places(object_type):
        log.searched.append(place)
        target = place_point(place)
        opened = open_containers and is_container(place.environment, place.link)
        if opened:
            seen, target = _look_into(place, wanted, log)
            if seen is not None:
                return seen
        seen = _look_from_places(
            robot, target, wanted, poses_per_place, log, place=None if opened else place
        )
        if seen is None and opened:  # over its rim from close by
            seen = _look_from_places(robot, target, wanted, poses_per_place, log, place)
        if seen is not None:
            return seen
    names = tuple(p.link for p in log.searched)
    hidden_by = blamed(log.failures, "occluded_by")
    raise SearchExhausted(
        f"no {object_type} seen from any place searched{camera_below(robot, log.searched)}"
        f"{_stayed_shut(log)}{culprit_clause(hidden_by, ())}: {', '.join(names) or 'none'}",
        object_designator=wanted,
        searched=names,
        occluded_by=hidden_by or None,
    )

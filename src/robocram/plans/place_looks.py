"""Looking at a place: at its frame, or, where the camera cannot be turned there, round it.

A search looks a little over a place's frame (``search.place_point``). A camera an arm
carries may not be turned to every point: the SO-101's five-joint arm, aimed at its
workcell table's frame 7.5 cm right of the mug, put its wrist into its shoulder, while
aimed at the mug it looked. So where the look at the frame fails (``PtuGoalUnreachable``,
blocked or beyond the joints), points of the same surface round it are looked at, nearest
to the frame first (ties: nearest to the robot), each followed by detecting, until one
shows the object. A look that succeeds at the frame is as before.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from robocram.designators import ObjectDesignator
from robocram.execution.failures import PerceptionObjectNotFound, PtuGoalUnreachable
from robocram.plans.basic_actions import detect, look, look_to_tilt_limit
from robocram.plans.environment_links import environment_link_pose
from robocram.plans.stands import map_pose
from robocram.tf import Pose, PoseStamped

AROUND_STEP = 0.075  # [m] between the points looked at round a place's frame
AROUND_RINGS = 2  # rings of points round it: up to 0.15 m away along the surface


def points_around(
    target: PoseStamped, robot_frame: str, place: tuple[str, str] | None = None
) -> list[PoseStamped]:
    """Points at ``target``'s height (map) stepped round it along the x and y axes of
    ``place``'s link (environment, link), or of the map, nearest to ``target`` first,
    ties broken by nearest to ``robot_frame``."""
    turned = Pose()
    if place is not None:
        turned = environment_link_pose(*place, "a place")
    tx, ty, tz = target.position
    centre = Pose((tx, ty, tz), turned.orientation)
    robot = map_pose(robot_frame).position
    offsets = [
        (i * AROUND_STEP, j * AROUND_STEP)
        for i in range(-AROUND_RINGS, AROUND_RINGS + 1)
        for j in range(-AROUND_RINGS, AROUND_RINGS + 1)
        if (i, j) != (0, 0)
    ]
    points = [(centre * Pose((dx, dy, 0.0))).position for dx, dy in offsets]
    keyed = sorted(
        zip(offsets, points, strict=True),
        key=lambda op: (
            round(math.hypot(*op[0]), 6),
            round(math.dist(op[1][:2], robot[:2]), 6),
            op[0],
        ),
    )
    return [PoseStamped("map", (p[0], p[1], tz)) for _, p in keyed]


def look_and_detect(
    wanted: ObjectDesignator,
    target: PoseStamped,
    place: tuple[str, str] | None = None,
    robot_frame: str | None = None,
) -> ObjectDesignator:
    """Look at ``target`` and detect ``wanted``; with ``place`` (environment, link) and
    ``robot_frame``, a look that cannot be had there is tried at :func:`points_around`.
    A head stopped at its tilt limit above ``target`` but with it in the lower part of its
    view has looked (:func:`~robocram.plans.basic_actions.look_to_tilt_limit`).

    Raises:
        PtuGoalUnreachable: the camera can be turned to none of the points (the first
            point's failure).
        PerceptionObjectNotFound: the object is not seen.
    """
    try:
        look_to_tilt_limit(target)
    except PtuGoalUnreachable as failure:
        if place is None or robot_frame is None:
            raise
        return _around(wanted, target, place, robot_frame, failure)
    return detect(wanted)


def _around(
    wanted: ObjectDesignator,
    target: PoseStamped,
    place: tuple[str, str] | None,
    robot_frame: str,
    first: PtuGoalUnreachable,
    detector: Callable[[ObjectDesignator], ObjectDesignator] = detect,
) -> ObjectDesignator:
    unseen: PerceptionObjectNotFound | None = None
    for point in points_around(target, robot_frame, place):
        try:
            look(point)
        except PtuGoalUnreachable:
            continue
        try:
            return detector(wanted)
        except PerceptionObjectNotFound as failure:
            unseen = unseen or failure
    if unseen is not None:
        raise unseen
    raise first


def detected_round(
    wanted: ObjectDesignator,
    target: PoseStamped,
    robot_frame: str,
    first: PtuGoalUnreachable,
    detector: Callable[[ObjectDesignator], ObjectDesignator] = detect,
) -> ObjectDesignator:
    """``wanted`` as seen looking at :func:`points_around` ``target`` (map axes), after
    the look at ``target`` itself failed with ``first``: the fetch looks at the object,
    and the SO-101's wrist camera could not be turned to the bowl 0.15 m right of its
    arm's plane, and saw it from beside it.

    Raises:
        PtuGoalUnreachable: the camera can be turned to no point round it (``first``).
        PerceptionObjectNotFound: no point it can be turned to shows it.
    """
    return _around(wanted, target, None, robot_frame, first, detector)

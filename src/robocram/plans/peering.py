"""Peering into an opened container: lower the head, step closer, look again.

A robot that does not see into a container from where it opened it does what a person
does: it looks again with its torso lower (an HSR's parked hand, raised with its lift,
hides the fridge's shelf from the top of the lift), then steps closer and looks down over
the rim (a drawer's walls, 21 cm high, hide a bowl on its floor from a camera 0.7 m away
at the height of a counter; from 0.5 m it is seen whole). Each step is a checked base
motion towards the point looked at; the first that cannot be driven ends the steps. Seen
from none, it steps back (a camera high over a fridge's shelf, a Boxy's at 1.45 m and
more, sees under the shelf from 0.8 m farther back, not from where it opened the door).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TypeVar

from robocram.execution.failures import PlanFailure
from robocram.plans.basic_actions import (
    heights_below,
    look,
    look_ahead,
    look_from_above,
    lower_torso,
    navigate,
)
from robocram.plans.container_access import OpenedContainer
from robocram.plans.known_robot import current_robot
from robocram.tf import Pose, PoseStamped

T = TypeVar("T")
PEER_STEPS = (0.1, 0.2, 0.3)  # [m] from the opening stand towards the point looked at
BACK_STEPS = (-0.4, -0.8)  # [m] the same, back: away from it (a move that cannot be
# driven is skipped)


def look_lower(point: PoseStamped, seen: Callable[[], T | None]) -> T | None:
    """What ``seen`` finds looking at ``point`` with the torso at each lower height of
    :data:`LOOK_HEIGHTS` in turn (a height the torso or the head cannot reach is skipped)."""
    for height in heights_below(current_robot()):
        try:
            lower_torso(height)
            look(point)
        except PlanFailure:
            continue
        found = seen()
        if found is not None:
            return found
    return None


def look_again(point: PoseStamped, seen: Callable[[], T | None]) -> T | None:
    """What ``seen`` finds looking at ``point`` from where the robot stands, the torso at
    its top first and then at each lower height (the head looks ahead before the torso
    rises: turned down, it would stop the lift on its way up); None if nothing."""
    look_ahead()
    try:
        look_from_above(point)
    except PlanFailure:
        return None
    return seen() or look_lower(point, seen)


def closer_stands(
    stand: Pose, point: PoseStamped, steps: tuple[float, ...] = PEER_STEPS
) -> list[Pose]:
    """``stand`` moved ``steps`` towards ``point`` (map, horizontally; a negative step
    away from it), turned as it is."""
    x, y, _ = stand.position
    dx, dy = point.position[0] - x, point.position[1] - y
    length = math.hypot(dx, dy) or 1.0
    return [
        Pose((x + step * dx / length, y + step * dy / length, 0.0), stand.orientation)
        for step in steps
    ]


def peer_into(
    opened: OpenedContainer, point: PoseStamped, seen: Callable[[], T | None]
) -> T | None:
    """What ``seen`` finds in ``opened`` after a look at ``point`` from its opening stand
    found nothing: looking lower from where the robot stands, then from each stand closer
    (from the top of the torso down), then from stands farther back; None when nothing
    was found."""
    found = look_lower(point, seen)
    for stand in closer_stands(opened.stand.pose, point):
        if found is not None:
            return found
        try:
            navigate(PoseStamped.from_pose("map", stand))
        except PlanFailure:
            break  # the container, or what stands beside it, is in the way
        found = look_again(point, seen)
    for stand in closer_stands(opened.stand.pose, point, BACK_STEPS):
        if found is not None:
            return found
        try:
            navigate(PoseStamped.from_pose("map", stand))
        except PlanFailure:
            continue
        found = look_again(point, seen)
    return found

"""Driving to a stand the lowered torso is in the way of: raise it and drive again.

A Boxy lowers its torso (0.586 m of travel) to look into a low drawer; standing near the
opened drawer then puts its arms' shoulders at the drawer's height, and every stand near
enough to reach the bowls was refused (the base itself fits). Only a refusal that names
nothing but links the torso moves raises it, so a drive that was refused for anything
else fails as before.
"""

from __future__ import annotations

import contextlib

from robocram.execution.failures import (
    NavigationPathBlocked,
    NavigationPoseUnreachable,
    PlanFailure,
)
from robocram.plans.basic_actions import move_torso, navigate
from robocram.plans.known_robot import KnownRobot, current_robot

TORSO_SLACK = 1e-3  # [m | rad] a torso this near its upper limit is up already
RAISES = (0.25, 0.5, 0.75, 1.0)  # fractions of the way up from where the torso is: it rises
# no higher than the stand needs (the arms' reach and grasps change with its height)


def torso_in_the_way(robot: KnownRobot, failure: NavigationPoseUnreachable) -> bool:
    """Whether ``failure`` (a refused goal, not a blocked path) names only links the torso
    moves, and the torso is below its upper limit: raised, they may clear what they met."""
    if isinstance(failure, NavigationPathBlocked) or not failure.robot_links:
        return False
    upper, now = robot.torso_limit("upper"), robot.torso_position()
    if upper is None or now is None or now >= upper - TORSO_SLACK:
        return False
    return set(failure.robot_links) <= robot.torso_carried_links()


def navigate_torso_up(target: object) -> None:
    """Drive the base to ``target``; where the goal is refused because of the lowered
    torso (:func:`torso_in_the_way`), raise the torso step by step (:data:`RAISES`) and
    drive again at each height; when none helps, the torso goes back down.

    Raises:
        NavigationPoseUnreachable: the goal is refused for anything else, or again with
            the torso up.
    """
    try:
        navigate(target)
        return
    except NavigationPoseUnreachable as failure:
        robot = current_robot()
        if not torso_in_the_way(robot, failure):
            raise
        refused = failure
    upper, start = robot.torso_limit("upper"), robot.torso_position()
    assert upper is not None and start is not None  # torso_in_the_way asked both
    for fraction in RAISES:
        try:
            move_torso(start + fraction * (upper - start))
        except PlanFailure:  # it cannot rise so far where it stands
            break
        try:
            navigate(target)
            return
        except NavigationPoseUnreachable as failure:
            if not torso_in_the_way(robot, failure):
                refused = failure
                break
            refused = failure
    with contextlib.suppress(PlanFailure):
        move_torso(start)  # no height helped: the torso goes back to where it was
    raise refused

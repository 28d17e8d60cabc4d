"""Driving off with an empty hand still round what it let go: lift the hand, drive again.

A hand that has just put a thing down backs off towards its wrist, but long fingers can
still reach down round the thing: Boxy put cup-1 at its seat with a top grasp, and with
the other arm holding cup-2 out over the table every drive to a stand for cup-2's seat
ran into cup-1 within 4 % of the way (the open fingers 14 mm from it on either side), and
backing the base out dragged them through the bowl and spoon beside it. Only a blocked
way whose robot links are all of a hand that holds nothing lifts that hand
(:func:`~robocram.plans.basic_actions.lift_hand`), so a drive blocked for anything else
fails as before.
"""

from __future__ import annotations

from robocram.execution.failures import NavigationPathBlocked, PlanFailure
from robocram.plans.basic_actions import lift_hand, navigate
from robocram.plans.known_robot import KnownRobot, current_robot


def empty_hand_in_the_way(robot: KnownRobot, failure: PlanFailure) -> str | None:
    """The arm whose empty hand holds up the blocked drive ``failure``: every robot link
    the way meets is of that hand, and it holds nothing; None otherwise."""
    if not isinstance(failure, NavigationPathBlocked) or not failure.robot_links:
        return None
    met = set(failure.robot_links)
    arms = robot.grasping_arms()
    holding = robot.held_objects(arms)
    return next((arm for arm in arms if arm not in holding and met <= robot.hand_links(arm)), None)


def navigate_empty_hand_up(target: object) -> None:
    """Drive the base to ``target``; where the way is blocked only by an empty hand
    (:func:`empty_hand_in_the_way`), lift that hand and drive again. The hand stays up.

    Raises:
        NavigationPoseUnreachable: the drive failed for anything else, the hand could not
            rise, or the drive failed again with it up (that failure).
    """
    try:
        navigate(target)
        return
    except NavigationPathBlocked as failure:
        robot = current_robot()
        arm = empty_hand_in_the_way(robot, failure)
        if arm is None or not _lifted(robot, arm):
            raise
    navigate(target)


def _lifted(robot: KnownRobot, arm: str) -> bool:
    """Whether ``arm``'s hand rose; a lift that failed in any way leaves the drive's
    failure to stand."""
    try:
        return lift_hand(robot, arm)
    except PlanFailure:
        return False

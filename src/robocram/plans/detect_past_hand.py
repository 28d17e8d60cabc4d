"""Detecting past the robot's own hand: a wrist camera's jaw swings out of its view."""

from __future__ import annotations

from robocram.designators import ObjectDesignator, a
from robocram.execution import perform
from robocram.execution.failures import PerceptionBlockedByRobot
from robocram.plans.known_robot import current_robot


def detect_past_hand(wanted: ObjectDesignator) -> ObjectDesignator:
    """Detect ``wanted``; where an arm's own link hides it, open the grippers that hold
    nothing and detect again: a wrist camera's jaw (the SO-101's moving jaw, closed before
    its camera) swings out of the view, as a pick-up opens it next anyway. The tabletop
    pick-up did so; the fetch after a search did not, and the SO-101 saw its jaw, not the
    mug it had found. A hand that holds something keeps it: opened, Boxy's tucked cup
    fell while its other hand fetched the second.

    Raises:
        PerceptionBlockedByRobot: a body link hides it (no gripper moves it), every hand
            holds something, or the hand still does with the free grippers open.
        PerceptionObjectNotFound: it is not seen.
    """
    try:
        found: ObjectDesignator = perform(a.motion(type="detecting", object=wanted))
    except PerceptionBlockedByRobot as blocked:
        if blocked.arm_parked is None:  # a body link: no gripper moves it
            raise
        robot = current_robot()
        arms = robot.grasping_arms()
        holding = robot.held_objects(arms)
        free = [arm for arm in arms if arm not in holding]
        if not free:
            raise
        for arm in free:  # a hand that holds something keeps it (a two-armed trip's first)
            perform(a.motion(type="opening", gripper=arm))
        found = perform(a.motion(type="detecting", object=wanted))
    return found

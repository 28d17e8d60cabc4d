"""Detecting past the robot's own hand: a wrist camera's jaw swings out of its view."""

from __future__ import annotations

from robocram.designators import ObjectDesignator, a
from robocram.execution import perform
from robocram.execution.failures import PerceptionBlockedByRobot
from robocram.plans.known_robot import current_robot


def detect_past_hand(wanted: ObjectDesignator) -> ObjectDesignator:
    """Detect ``wanted``; where an arm's own link hides it, open the grippers and detect
    again: a wrist camera's jaw (the SO-101's moving jaw, closed before its camera) swings
    out of the view, as a pick-up opens it next anyway. The tabletop pick-up did so; the
    fetch after a search did not, and the SO-101 saw its jaw, not the mug it had found.

    Raises:
        PerceptionBlockedByRobot: a body link hides it (no gripper moves it), or the hand
            still does with the grippers open.
        PerceptionObjectNotFound: it is not seen.
    """
    try:
        found: ObjectDesignator = perform(a.motion(type="detecting", object=wanted))
    except PerceptionBlockedByRobot as blocked:
        if blocked.arm_parked is None:  # a body link: no gripper moves it
            raise
        for arm in current_robot().grasping_arms():
            perform(a.motion(type="opening", gripper=arm))
        found = perform(a.motion(type="detecting", object=wanted))
    return found

"""Perception and looking failures: the camera, the pan-tilt unit and searching."""

from __future__ import annotations

from robocram.designators import ObjectDesignator
from robocram.execution.failures.high_level import HighLevelFailure
from robocram.execution.failures.low_level import LowLevelFailure


class PerceptionLowLevelFailure(LowLevelFailure):
    """A perception request failed."""

    summary = "perception failed"


class PerceptionObjectNotFound(PerceptionLowLevelFailure):
    """No object in view matches the designator."""

    object_designator: ObjectDesignator | None = None
    occluded_by: tuple[str, ...] | None = None  # what hid a fitting object in view, most first
    summary = "no object matching the designator was seen"
    hint = "look somewhere else or relax the object description"


class PerceptionBlockedByRobot(PerceptionObjectNotFound):
    """The robot's own link stands between its camera and an object that fits."""

    link: str | None = None
    target: str | None = None
    arm_parked: bool | None = None  # the blocking link's arm is parked (None: on no arm)
    summary = "the robot's own link blocks the camera's view"
    hint = "the message says what moves that link out of the view"


class PtuLowLevelFailure(LowLevelFailure):
    """A pan-tilt unit (neck) motion failed."""

    summary = "the pan-tilt motion failed"


class PtuGoalUnreachable(PtuLowLevelFailure):
    """The look target needs pan/tilt angles outside the joint limits."""

    target: object | None = None
    limits: object | None = None
    summary = "the pan-tilt goal is outside the joint limits"
    hint = "turn the base towards the target first"


class PtuPathBlocked(PtuGoalUnreachable):
    """Turning the head to the look target runs into something; the head did not move."""

    colliding_pairs: tuple[tuple[str, str], ...] | None = None  # (robot link, object)
    path_fraction: float | None = None  # [0..1] where along the turn it collides (1: the goal)
    summary = "the head's turn to the look target is blocked"
    hint = "move the base, or what the message names, so the head can turn freely"


class PtuGoalNotReached(PtuLowLevelFailure):
    """The pan-tilt unit stopped away from its goal."""

    target: object | None = None
    reached: object | None = None
    below_tilt: bool = False  # the target lies below the axis tilted down to its limit
    # the target's angles off the optical axis as turned, as shares of the camera's half
    # fields (aside: + right; below: + down; 1 at the view's edge); None: not measured
    view_share: tuple[float, float] | None = None
    summary = "the pan-tilt unit did not reach its goal"
    hint = "retry the look"


class LookingHighLevelFailure(HighLevelFailure):
    """Looking at a target failed after all retries."""

    target: object | None = None
    summary = "looking at the target failed"
    hint = "move the base so the target is in front of the robot"


class ObjectNowhereToBeFound(HighLevelFailure):
    """Searching all candidate locations did not find the object."""

    object_designator: ObjectDesignator | None = None
    searched: list[object] | None = None
    summary = "the object is nowhere to be found"
    hint = "extend the search locations or check the object description"

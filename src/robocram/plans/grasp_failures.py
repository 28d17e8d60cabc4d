"""Failures of picking up and placing: what was tried and why each try failed."""

from __future__ import annotations

from robocram.execution.failures import (
    HighLevelFailure,
    ManipulationLowLevelFailure,
    ManipulationPoseUnreachable,
    ObjectUnreachable,
)


class ObjectUngraspable(ObjectUnreachable):
    """No grasp of the object fits the hand: the object is wider than the hand opens."""

    object_name: str | None = None
    arm: str | None = None
    hand_width: float | None = None  # [m]
    needed_width: float | None = None  # [m]
    summary = "no grasp of the object fits the hand"
    hint = "use an arm with a wider hand, or declare a handle or wall (docs/grasping.md)"


class PickUpFailed(ObjectUnreachable):
    """Every arm and grasp was tried and none picked the object up."""

    object_name: str | None = None
    causes: list[Exception] | None = None
    summary = "the object could not be picked up"
    hint = "stand elsewhere (a reachable_for location) or clear the way to the object"


class PickUpUnreachable(PickUpFailed, ManipulationPoseUnreachable):
    """Every pre-grasp or grasp pose tried was out of the arms' reach (IK found none).

    Also a :class:`ManipulationPoseUnreachable`, so a handler of the low-level failure
    catches a pick-up whose every try was out of reach.
    """

    summary = "no grasp of the object was within the arms' reach"


class PlacingFailed(HighLevelFailure):
    """The held object could not be put down at the target."""

    object_name: str | None = None
    target: object | None = None
    causes: list[Exception] | None = None
    summary = "the object could not be placed"
    hint = "pick a target nearer the robot, or on a free, level part of the surface"


class ObjectMovedSinceSeen(ManipulationLowLevelFailure):
    """The object no longer lies where the pick's grasps were computed from: an earlier
    try of the pick moved it (the HSR's first rim grasp of a bowl in a drawer pushed it
    5.4 cm, and the next grasp, aimed at where it had been, caught the rim off its middle,
    so the bowl was put down 5.5 cm off its seat)."""

    object_name: str | None = None
    moved: float | None = None  # [m] from where it was seen to where it lies now
    summary = "the object moved since it was seen"
    hint = "perceive it again and pick it where it lies now"

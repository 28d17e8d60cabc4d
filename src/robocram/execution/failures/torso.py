"""Torso failures: the prismatic lift joint of the robot."""

from __future__ import annotations

from robocram.execution.failures.low_level import LowLevelFailure


class TorsoLowLevelFailure(LowLevelFailure):
    """A torso motion failed."""

    summary = "the torso motion failed"


class TorsoGoalUnreachable(TorsoLowLevelFailure):
    """The torso goal lies outside the joint limits."""

    goal: float | None = None
    limits: tuple[float, float] | None = None
    summary = "the torso goal is outside the joint limits"
    hint = "pick a goal [m] within the limits"


class TorsoPathBlocked(TorsoGoalUnreachable):
    """The torso's way to its goal runs into something (a shelf above the head); it did
    not move."""

    colliding_pairs: tuple[tuple[str, str], ...] | None = None  # (robot link, object)
    path_fraction: float | None = None  # [0..1] where along the way it collides (1: the goal)
    summary = "the torso's way to its goal is blocked"
    hint = "stand elsewhere, or move what the message names out of the way"


class TorsoGoalNotReached(TorsoLowLevelFailure):
    """The torso stopped away from its goal."""

    goal: float | None = None
    limits: tuple[float, float] | None = None
    reached: object | None = None
    summary = "the torso did not reach its goal"
    hint = "check the goal against the joint limits or retry"

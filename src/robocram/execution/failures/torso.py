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


class TorsoGoalNotReached(TorsoLowLevelFailure):
    """The torso stopped away from its goal."""

    goal: float | None = None
    limits: tuple[float, float] | None = None
    reached: object | None = None
    summary = "the torso did not reach its goal"
    hint = "check the goal against the joint limits or retry"

"""Flying failures: quadrotor motions."""

from __future__ import annotations

from robocram.execution.failures.high_level import HighLevelFailure
from robocram.execution.failures.low_level import LowLevelFailure


class FlyingLowLevelFailure(LowLevelFailure):
    """A flight motion failed."""

    summary = "the flight motion failed"


class FlyingGoalNotReached(FlyingLowLevelFailure):
    """The quadrotor stopped away from its target."""

    fields = ("target", "reached", "error")
    summary = "the quadrotor did not reach its goal"
    hint = "retry, or check for wind and obstacles"


class FlyingGoalInCollision(HighLevelFailure):
    """The flight target or the straight path to it hits an obstacle."""

    fields = ("target", "colliding")
    summary = "the flying goal is in collision"
    hint = "pick a target in free space, or fly around the obstacle"

"""Flying failures: quadrotor motions."""

from __future__ import annotations

from robocram.execution.failures.high_level import HighLevelFailure
from robocram.execution.failures.low_level import LowLevelFailure


class FlyingLowLevelFailure(LowLevelFailure):
    """A flight motion failed."""

    summary = "the flight motion failed"


class FlyingGoalNotReached(FlyingLowLevelFailure):
    """The quadrotor stopped away from its target."""

    target: object | None = None
    reached: object | None = None
    error: float | None = None
    summary = "the quadrotor did not reach its goal"
    hint = "retry, or check for wind and obstacles"


class FlyingGoalInCollision(HighLevelFailure):
    """The flight target or the straight path to it hits an obstacle."""

    target: object | None = None
    colliding: list[str] | None = None
    summary = "the flying goal is in collision"
    hint = "pick a target in free space, or fly around the obstacle"

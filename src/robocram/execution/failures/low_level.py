"""Low-level failures: a robot resource (arm, gripper, torso, base, head) missed its goal."""

from __future__ import annotations

from robocram.execution.failures.plan_failure import PlanFailure


class LowLevelFailure(PlanFailure):
    """A process module or low-level function could not do what it was asked."""

    summary = "a low-level action failed"
    hint = "inspect the data, then retry or pick another goal"


class ActionlibActionTimedOut(LowLevelFailure):
    """A low-level action ran longer than its time budget."""

    action: str | None = None
    timeout: float | None = None
    summary = "the low-level action timed out"
    hint = "raise the timeout [s] or check that the action server is running"

"""The root of high-level failures: a whole action (fetch, deliver, search) gave up."""

from __future__ import annotations

from robocram.execution.failures.plan_failure import PlanFailure


class HighLevelFailure(PlanFailure):
    """An action plan failed after its own recovery was exhausted."""

    summary = "a high-level action failed"
    hint = "recover at the plan level, e.g. with another location or object"

"""Failures and errors of the plan language itself: composite failures, waits, misuse."""

from __future__ import annotations

from robocram.execution.failures.plan_failure import PlanFailure


class CompositeFailure(PlanFailure):
    """Every alternative of try_all / try_in_order failed; ``failures`` lists them in order."""

    form: str | None = None
    failures: list[PlanFailure] | None = None
    summary = "all alternatives failed"
    hint = "see `failures` for each alternative's reason"


class FluentWaitTimeout(PlanFailure):
    """A wait on a fluent ran out of time before the condition held."""

    fluent: object | None = None
    timeout: float | None = None
    value: object | None = None
    summary = "the fluent condition did not hold in time"
    hint = "raise the timeout [s] or check what should set the fluent"


class NotInTopLevel(RuntimeError):
    """A plan form ran outside a top level.

    A programming error, not a plan failure: deriving from PlanFailure would let a
    ``PlanFailure`` handler retry a bug forever, so it derives from RuntimeError.
    """

    def __init__(self, form: str) -> None:
        super().__init__(
            f"{form} needs a running task but was called outside a top level; "
            f"run the plan with run_top_level(plan) or inside `with top_level():`"
        )
        self.form = form


class RetryOutsideHandler(RuntimeError):
    """retry() was called outside a failure handler, where there is nothing to retry."""

    def __init__(self) -> None:
        super().__init__(
            "retry() called outside a failure handler; call it inside a handler given to "
            "with_failure_handling(body, {FailureType: handler})"
        )

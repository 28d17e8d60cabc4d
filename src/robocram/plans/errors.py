"""Errors of robot-independent plans started where they cannot run (a setup mistake)."""

from __future__ import annotations

from robocram.execution.failures import PerceptionObjectNotFound, SetupFailure


class PlanSetupError(SetupFailure, RuntimeError):
    """A plan needs knowledge the current environment does not give (no robot, say)."""


class SearchExhausted(PerceptionObjectNotFound):
    """Every candidate place was looked at and the object was in none of them."""

    searched: tuple[str, ...] | None = None  # the places looked at, in order
    hint = "put the object's usual place into the KB (usual_location/3) or search elsewhere"

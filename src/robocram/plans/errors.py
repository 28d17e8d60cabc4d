"""Errors of robot-independent plans started where they cannot run (a setup mistake)."""

from __future__ import annotations

from robocram.execution.failures import SetupFailure


class PlanSetupError(SetupFailure, RuntimeError):
    """A plan needs knowledge the current environment does not give (no robot, say)."""

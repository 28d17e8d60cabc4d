"""Errors of robot-independent plans started where they cannot run (a setup mistake)."""

from __future__ import annotations


class PlanSetupError(RuntimeError):
    """A plan needs knowledge the current environment does not give (no robot, say)."""

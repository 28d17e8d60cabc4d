"""The motion layer's errors: a motion asked for wrongly (not a blocked path).

A blocked path is a plan failure (``ManipulationPathBlocked``, ``NavigationPathBlocked``
in ``execution.failures``), which plans handle by retrying; a :class:`MotionError` is a
programming error: an unknown joint, a malformed path, a bad resolution. A
:class:`MotionInputError` is one whose culprit is a value the caller gave (a goal that is
not finite, a size past one of the motion layer's bounds): a set-up failure, so a
process module reports it as its caller's mistake, never as a bug in the module.
"""

from __future__ import annotations

from robocram.execution.failures import SetupFailure


class MotionError(ValueError):
    """A motion, path or trajectory was asked for with bad input; the message says which."""


class MotionInputError(SetupFailure, MotionError):
    """A goal, path or size no motion can take: it names the joint or size and the bound."""

    joint: str | None = None
    value: float | None = None
    bound: float | None = None
    summary = "the motion was asked for with a value it cannot take"
    hint = "the caller's mistake, not the planner's: fix the value the message names"

"""The batch benchmark's plan, in its own module so spawned workers and Ray actors import it."""

from __future__ import annotations

from robocram.logic import current_kb
from robocram.plans import PickResult, pick_up
from robocram.tf import PoseStamped

SETTLE = 0.5  # [s] of simulated time after the lift


def pick_and_settle(look_target: PoseStamped) -> PickResult:
    """Pick up the mug, then let the world run: a variant's worth of projection work."""
    result = pick_up(look_target)
    current_kb().first("world(W), simulate(W, S)", S=SETTLE)
    return result

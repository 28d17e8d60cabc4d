"""A legged robot tries again crouched where standing it reaches too high.

A humanoid's shoulders stand high: TALOS holds the bowl drawer's handle, 0.64 m under
them, only with its body 0.15 m or more lower, and lifts the bowl out of the open drawer
only 0.20-0.25 m lower (issue 37). A robot whose knowledge base grounds ``crouching``
motions (it stands on legs it bends) opens, closes and fetches from a container crouched
when standing failed, at each of :data:`DEPTHS` in turn, and stands up again before it
drives elsewhere: its camera looks, and its reach costmaps hold, from its standing height.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import PlanFailure
from robocram.logic import current_kb

DEPTHS = (0.20, 0.25)  # [m] below standing, tried in turn (0.15: the drawer opens, but the
# open handle is not held again to close it; 0.30: the bowl is not put down: zoo32)


def can_crouch() -> bool:
    """Whether the current robot crouches: its knowledge base grounds ``crouching``."""
    kb = current_kb()
    if not kb.defines("grounded_motion_type/1"):
        return False
    return any(True for _ in kb.query("grounded_motion_type(crouching)"))


def crouch(depth: float) -> object:
    """Bend the legs until the body stands ``depth`` [m] below standing (0: stand up)."""
    return perform(a.motion(type="crouching", depth=depth))


def stand_up(depth: float) -> None:
    """After a step done ``depth`` [m] crouched (0: standing, nothing to do), stand up;
    a way up that is blocked leaves the robot crouched (it drives so too)."""
    if depth > 0.0:
        with contextlib.suppress(PlanFailure):
            crouch(0.0)


@contextlib.contextmanager
def crouched(depth: float) -> Iterator[None]:
    """Inside, the robot crouches ``depth`` [m] (0: it stands); it stands up after."""
    if depth > 0.0:
        crouch(depth)
    try:
        yield
    finally:
        stand_up(depth)

"""A legged robot tries again crouched where standing it reaches too high.

A humanoid's shoulders stand high: TALOS holds the bowl drawer's handle, 0.64 m under
them, only with its body 0.15 m or more lower, and lifts the bowl out of the open drawer
only 0.20-0.25 m lower (issue 37). A robot whose knowledge base grounds ``crouching``
motions (it stands on legs it bends) opens, closes and fetches from a container crouched
when standing failed, at each of :data:`DEPTHS` in turn, and stands up again before it
drives elsewhere: its camera looks, and its reach costmaps hold, from its standing height.
A fetch crouches at each of its stands after the drive (:func:`crouched_at_stand`):
Centauro, crouched where the standing fetch left it, met the open drawer with its hips on
the way down; it lifts the bowl out of it only from a stand 0.75 m back, 0.25 m down (zoo37).
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

from robocram.designators import a
from robocram.designators.grounded_designator import lists_motion_type
from robocram.execution import perform
from robocram.execution.failures import PlanFailure
from robocram.logic import current_kb
from robocram.plans.basic_actions import park_arms

DEPTHS = (0.20, 0.25)  # [m] below standing, tried in turn (0.15: the drawer opens, but the
# open handle is not held again to close it; 0.30: the bowl is not put down: zoo32)


def can_crouch() -> bool:
    """Whether the current robot crouches: its knowledge base grounds ``crouching``."""
    return lists_motion_type(current_kb(), "crouching")


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


@contextlib.contextmanager
def crouched_at_stand(depth: float) -> Iterator[None]:
    """Inside, the robot crouches ``depth`` [m] where it stands (0: it stands); it stands up
    after, holding what it picked; after a failure inside, the arms parked first (a hand
    left out over the thing would meet it on the way up)."""
    if depth > 0.0:
        crouch(depth)
    try:
        yield
    except PlanFailure:
        if depth > 0.0:
            with contextlib.suppress(PlanFailure):
                park_arms()
        stand_up(depth)
        raise
    stand_up(depth)

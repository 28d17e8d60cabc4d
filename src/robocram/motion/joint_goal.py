"""A joint goal as a motion takes it: finite values, continuous joints the short way round.

A continuous joint has no limits, so a goal of 1e4 rad was walked literally (55,597
points) and 1e300 never ended. Its goal is an angle: the motion turns the short way to
it (at most half a turn), ending at the goal's value up to whole turns. A goal farther
than :data:`CONTINUOUS_GOAL_BOUND` from zero is refused: past it the angle it means is
lost to rounding, so it cannot be what the caller meant. A goal that is not finite is
refused for every joint, naming it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from robocram.motion.errors import MotionInputError
from robocram.robots import LoadedDescription

CONTINUOUS_GOAL_BOUND = 1e3  # [rad] ~159 turns; beyond it a goal angle is not meant


def motion_goal(
    desc: LoadedDescription,
    joints: Sequence[str],
    start: Sequence[float],
    goal: Mapping[str, float],
) -> list[float]:
    """The end values [rad | m] of ``joints`` a motion from ``start`` to ``goal`` goes to.

    Values are ``goal``'s as they are, but a continuous joint more than half a turn away,
    which ends the short way round (the goal's angle, whole turns from its value).

    Raises:
        MotionInputError: a goal value is not a finite number, or a continuous joint's is
            beyond :data:`CONTINUOUS_GOAL_BOUND` (naming the joint and the bound).
    """
    end = []
    for name, here in zip(joints, start, strict=True):
        value = finite_goal(name, goal[name])
        if desc.model.joints[name].type == "continuous":
            value = _short_way(name, here, value)
        end.append(value)
    return end


def finite_goal(joint: str, raw: object) -> float:
    """``raw`` as the goal [rad | m] of ``joint``, refused unless a finite number: callers
    that clamp goals to limits check first (inf must not become the upper limit).

    Raises:
        MotionInputError: naming the joint.
    """
    try:
        value = float(raw)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        value = math.nan
    if not math.isfinite(value):
        raise MotionInputError(
            f"joint {joint!r}: goal {raw!r} is not a finite number; give a value in its limits",
            joint=joint,
        )
    return value


def _short_way(joint: str, here: float, goal: float) -> float:
    if abs(goal) > CONTINUOUS_GOAL_BOUND:
        raise MotionInputError(
            f"continuous joint {joint!r}: goal {goal} rad is beyond the bound of "
            f"{CONTINUOUS_GOAL_BOUND:g} rad (CONTINUOUS_GOAL_BOUND); give the angle, "
            "e.g. within [-pi, pi]",
            joint=joint,
            value=goal,
            bound=CONTINUOUS_GOAL_BOUND,
        )
    turn = goal - here
    if abs(turn) <= math.pi:
        return goal  # the short way already: the goal exactly as given
    return here + math.remainder(turn, 2.0 * math.pi)

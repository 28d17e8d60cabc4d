"""The goals clause code puts in a continuation for the machine alone: calls and inline runs.

Clause code runs the tests, `is/2` and `=/2` goals that lead a body in its own frame.
Those that follow a call cannot: the call runs first, in the machine. Each run of them
becomes one goal `(fn, values, INLINE)`, and the machine calls `fn(trail, *values)`
(true to go on, false to fail) without looking up a predicate. Calls are built the same
way, as `((name, arity), args, CALL)` instead of `Term`s: a plain tuple costs a third
of a `Term` to make, and the machine looks the predicate up by the ready-made key. The
private markers tell these from any Python tuple a program passed as a goal (that stays
a type error); they never appear in a term a program can read.

>>> goal = (lambda trail, x: x > 1, (2,), INLINE)
>>> goal[2] is INLINE and goal[0]([], *goal[1])
True
"""

from __future__ import annotations

__all__ = ["CALL", "INLINE", "GoalMark"]


class GoalMark:
    """The last item of a goal tuple that clause code built: CALL or INLINE."""

    __slots__ = ("name",)

    def __init__(self, name: str) -> None:
        self.name = name

    def __repr__(self) -> str:
        return self.name


CALL = GoalMark("CALL")
INLINE = GoalMark("INLINE")

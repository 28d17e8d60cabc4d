"""The goals clause code puts in a continuation for the machine alone: calls and inline runs.

Clause code runs the tests, `is/2` and `=/2` goals that lead a body in its own frame.
Those that follow a call cannot: the call runs first, in the machine. Each run of them
becomes one goal `(fn, values, INLINE)`, and the machine calls `fn(trail, values)`
(true to go on, false to fail) without looking up a predicate. Calls are built the same
way, as `((name, arity), args, CALL)` instead of `Term`s: a plain tuple costs a third
of a `Term` to make, and the machine looks the predicate up by the ready-made key. The
private markers tell these from any Python tuple a program passed as a goal (that stays
a type error); they never appear in a term a program can read.

Control constructs in a clause body are compiled the same way, so that the machine runs
them without looking up `;/2` or `,/2`: `(first, rest, SEQ)` is a conjunction,
`(left, right, DISJ)` a disjunction, `(cond, (then, else), ITE)` an if-then-else,
`(cond, then, IFTHEN)` an if-then and `(goal, None, NOT)` a negation; the machine ends a
condition with the cell `("!", b, next)`, the atom `!` with choicepoint `b` as its cut
barrier. Each part is one goal (a SEQ for several); a then-branch that is just `true` is
None (nothing to run after the cut).

>>> goal = (lambda trail, values: values[0] > 1, (2,), INLINE)
>>> goal[2] is INLINE and goal[0]([], goal[1])
True
"""

from __future__ import annotations

__all__ = ["CALL", "DISJ", "IFTHEN", "INLINE", "ITE", "MARKS", "NOT", "SEQ", "GoalMark"]


class GoalMark:
    """The last item of a goal tuple that clause code built: CALL, INLINE or a control mark."""

    __slots__ = ("name",)

    def __init__(self, name: str) -> None:
        self.name = name

    def __repr__(self) -> str:
        return self.name


CALL = GoalMark("CALL")
INLINE = GoalMark("INLINE")
SEQ = GoalMark("SEQ")
DISJ = GoalMark("DISJ")
ITE = GoalMark("ITE")
IFTHEN = GoalMark("IFTHEN")
NOT = GoalMark("NOT")
MARKS = (CALL, INLINE, SEQ, DISJ, ITE, IFTHEN, NOT)

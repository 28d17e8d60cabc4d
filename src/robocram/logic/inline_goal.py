"""A run of inline goals later in a clause body, compiled to one Python function.

Clause code runs the tests, `is/2` and `=/2` goals that lead a body in its own frame.
Those that follow a call cannot: the call runs first, in the machine. Each run of them
becomes one `InlineGoal(fn, values)` in the continuation, and the machine calls
`fn(trail, *values)` (true to go on, false to fail) without looking up a predicate.
It is a goal only the machine sees: it never appears in a term a program can read.

Calls in the continuation are built the same way, as plain tuples `(name, args, CALL)`
instead of `Term`s: a tuple costs a third of a `Term` to make, and the private `CALL`
marker tells the machine's tuple from any Python tuple a program passed as a goal.
"""

from __future__ import annotations

from typing import Any

__all__ = ["CALL", "InlineGoal"]


class _CallMark:
    """The type of CALL: the last item of a call goal that clause code built."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "CALL"


CALL = _CallMark()


class InlineGoal(tuple[Any, tuple[Any, ...]]):
    """`(fn, values)`: the compiled goals and the clause values they read.

    >>> goal = tuple.__new__(InlineGoal, (lambda trail, x: x > 1, (2,)))
    >>> goal[0]([], *goal[1])
    True
    """

    __slots__ = ()

    def __repr__(self) -> str:
        return f"<inline goals of {len(self[1])} values>"

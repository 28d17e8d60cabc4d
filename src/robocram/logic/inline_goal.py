"""A run of inline goals later in a clause body, compiled to one Python function.

Clause code runs the tests, `is/2` and `=/2` goals that lead a body in its own frame.
Those that follow a call cannot: the call runs first, in the machine. Each run of them
becomes one `InlineGoal(fn, values)` in the continuation, and the machine calls
`fn(trail, *values)` (true to go on, false to fail) without looking up a predicate.
It is a goal only the machine sees: it never appears in a term a program can read.
"""

from __future__ import annotations

from typing import Any

__all__ = ["InlineGoal"]


class InlineGoal(tuple[Any, tuple[Any, ...]]):
    """`(fn, values)`: the compiled goals and the clause values they read.

    >>> goal = tuple.__new__(InlineGoal, (lambda trail, x: x > 1, (2,)))
    >>> goal[0]([], *goal[1])
    True
    """

    __slots__ = ()

    def __repr__(self) -> str:
        return f"<inline goals of {len(self[1])} values>"

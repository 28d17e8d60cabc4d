"""Integer arithmetic in compiled clauses: a Python operator where it agrees with ISO.

`X is (P * 100) // A` compiled to `ap2("//", ...)` costs two Python calls per
evaluation (the dispatch and the integer check of arith.py). For integer operands that
meet a function's condition, Python's operator gives ISO's result; any other operands
take `ap2`, with its checks and errors.
"""

from __future__ import annotations

__all__ = ["INT_FAST", "int_fast"]

# Integer functions with a Python operator that agrees with ISO for integer operands
# meeting the condition: (condition, operation) on the operands {0} and {1}.
INT_FAST = {
    "//": ("{0} >= 0 and {1} > 0", "{0} // {1}"),  # ISO truncates, Python floors
    "rem": ("{0} >= 0 and {1} > 0", "{0} % {1}"),
    "mod": ("{1} != 0", "{0} % {1}"),  # both take the divisor's sign
    "div": ("{1} != 0", "{0} // {1}"),  # both floor
    ">>": ("{1} >= 0", "{0} >> {1}"),
    "/\\": ("", "{0} & {1}"),
    "\\/": ("", "{0} | {1}"),
    "xor": ("", "{0} ^ {1}"),
    "min": ("", "({0} if {0} <= {1} else {1})"),
    "max": ("", "({0} if {0} >= {1} else {1})"),
}


def int_fast(name: str, a: str, b: str, x: str, y: str, k: str) -> str:
    """The expression of `name(a, b)`: its operator on two integers meeting its condition,
    else `ap2(k, ...)` (`k` the constant holding `name`); `x`, `y` fresh temporaries.

    Both operands are evaluated first, in order, as the call evaluates them: `&`, not
    `and`, so that the second is evaluated when the first is no integer.

    >>> int_fast("mod", "a", "b", "x", "y", "k")
    '(x % y if (type(x := a) is int) & (type(y := b) is int) and y != 0 else ap2(k, x, y))'
    """
    condition, operation = INT_FAST[name]
    test = f"(type({x} := {a}) is int) & (type({y} := {b}) is int)"
    if condition:
        test += f" and {condition.format(x, y)}"
    return f"({operation.format(x, y)} if {test} else ap2({k}, {x}, {y}))"

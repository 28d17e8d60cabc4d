"""Decimal text of integers of any size (Python refuses more than 4,300 digits by default).

The limit guards `int(str)` against quadratic work on untrusted input; the engine caps
integers itself (arith.MAX_INTEGER_BITS), so it converts in halves instead of raising a
raw `ValueError` from `format("~d", [2**100000])` or a long literal.
"""

from __future__ import annotations

__all__ = ["int_text", "text_int"]

_SAFE_BITS = 12_000  # about 3,600 digits: under Python's default limit
_SAFE_DIGITS = 4_000


def int_text(n: int) -> str:
    """`str(n)` for any size of `n`.

    >>> int_text(2**20000)[:5], len(int_text(2**20000))
    ('39802', 6021)
    """
    if n.bit_length() <= _SAFE_BITS:
        return str(n)
    if n < 0:
        return "-" + int_text(-n)
    half = int(n.bit_length() * 0.30103) // 2
    high, low = divmod(n, 10**half)
    return int_text(high) + int_text(low).zfill(half)


def text_int(digits: str) -> int:
    """`int(digits)` for any number of decimal digits.

    >>> text_int("1" * 9000) == int_text(int("1" * 3000)) and False or text_int("12")
    12
    """
    if len(digits) <= _SAFE_DIGITS:
        return int(digits)
    half = len(digits) // 2
    return text_int(digits[:half]) * 10 ** (len(digits) - half) + text_int(digits[half:])

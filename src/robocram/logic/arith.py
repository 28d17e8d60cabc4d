"""Arithmetic evaluation with ISO error terms (the built-ins are in builtin_arith).

>>> from robocram.logic.reader import read_query
>>> evaluate(read_query("2 ** 3 + 7 // 2 - max(1, 4.0)")[0])
7.0
"""

from __future__ import annotations

import math
from collections.abc import Callable

from robocram.logic.errors import (
    PrologEvaluationError,
    PrologInstantiationError,
    PrologResourceError,
    PrologTypeError,
)
from robocram.logic.terms import PString, Term, Var
from robocram.logic.value import Value

__all__ = ["BINARY_FUNCTIONS", "MAX_INTEGER_BITS", "apply_binary", "evaluate"]

Number = int | float

# The largest integer an operation that can explode in one step (`**`, `^`, `<<`) may
# produce: 2**20 bits (about 315,000 decimal digits). Bigger results raise
# resource_error(memory) instead of allocating gigabytes. The current_prolog_flag
# max_integer_bits reports it.
MAX_INTEGER_BITS = 1 << 20


def _too_big(name: str, bits: int) -> PrologResourceError:
    return PrologResourceError(
        "memory",
        f"{name}: the result would have about {bits} bits, over the engine's limit of"
        f" {MAX_INTEGER_BITS} bits (arith.MAX_INTEGER_BITS)",
    )


def _shift_left(a: int, b: int) -> int:
    if b > 0 and a and a.bit_length() + b > MAX_INTEGER_BITS:
        raise _too_big("<<", a.bit_length() + b)
    return a << b if b >= 0 else a >> -b


def _int_only(name: str, fn: Callable[[int, int], int]) -> Callable[[Number, Number], Number]:
    def checked(a: Number, b: Number) -> Number:
        for x in (a, b):
            if type(x) is not int:
                raise PrologTypeError("integer", x, f"{name}: {x!r} is not an integer")
        if name in ("//", "mod", "rem", "div") and b == 0:
            raise PrologEvaluationError("zero_divisor", f"{name}: division by zero")
        return fn(int(a), int(b))

    return checked


def _divide(a: Number, b: Number) -> Number:
    if b == 0:
        if type(b) is int or type(a) is int:
            raise PrologEvaluationError("zero_divisor", f"{a!r} / {b!r}: division by zero")
        raise PrologEvaluationError("undefined", f"{a!r} / {b!r}: undefined")
    if type(a) is int and type(b) is int and a % b == 0:
        return a // b
    return a / b


def _power(a: Number, b: Number) -> Number:
    if type(a) is int and type(b) is int:
        if b < 0 and a not in (1, -1):
            raise PrologTypeError("float", a, f"{a} ^ {b}: negative integer power; use a float")
        if b > 0 and abs(a) > 1 and (abs(a).bit_length() - 1) * b > MAX_INTEGER_BITS:
            raise _too_big("**", (abs(a).bit_length() - 1) * b)
        return int(a**b) if b >= 0 else int(a**b)
    return float(a) ** float(b)


def _trunc_div(a: int, b: int) -> int:
    """`a // b` truncated toward zero, exact for big integers (no float on the way)."""
    q = abs(a) // abs(b)
    return q if (a < 0) == (b < 0) else -q


def _rem(a: int, b: int) -> int:
    return a - b * _trunc_div(a, b)


def _round(x: Number) -> int:
    return int(math.floor(x + 0.5)) if x >= 0 else -int(math.floor(-x + 0.5))


def _sign(x: Number) -> Number:
    if type(x) is int:
        return (x > 0) - (x < 0)
    return math.copysign(1.0, x) if x != 0 else 0.0


_BINARY: dict[str, Callable[[Value, Value], Number]] = {
    "+": lambda a, b: a + b,
    "-": lambda a, b: a - b,
    "*": lambda a, b: a * b,
    "/": _divide,
    "//": _int_only("//", _trunc_div),
    "mod": _int_only("mod", lambda a, b: a % b),
    "rem": _int_only("rem", _rem),
    "div": _int_only("div", lambda a, b: a // b),
    "min": lambda a, b: a if a <= b else b,
    "max": lambda a, b: a if a >= b else b,
    "**": lambda a, b: _power(a, b) if type(a) is int and type(b) is int else float(a) ** float(b),
    "^": _power,
    "atan2": lambda a, b: math.atan2(a, b),
    "atan": lambda a, b: math.atan2(a, b),
    "copysign": lambda a, b: math.copysign(a, b),
    "log": lambda a, b: math.log(b) / math.log(a),
    ">>": _int_only(">>", lambda a, b: a >> b if b >= 0 else _shift_left(a, -b)),
    "<<": _int_only("<<", _shift_left),
    "/\\": _int_only("/\\", lambda a, b: a & b),
    "\\/": _int_only("\\/", lambda a, b: a | b),
    "xor": _int_only("xor", lambda a, b: a ^ b),
    "gcd": _int_only("gcd", math.gcd),
}

_UNARY: dict[str, Callable[[Value], Number]] = {
    "-": lambda a: -a,
    "+": lambda a: a,
    "abs": abs,
    "sign": _sign,
    "min": lambda a: a,
    "sqrt": math.sqrt,
    "sin": math.sin,
    "cos": math.cos,
    "tan": math.tan,
    "asin": math.asin,
    "acos": math.acos,
    "atan": math.atan,
    "exp": math.exp,
    "log": math.log,
    "log2": math.log2,
    "sinh": math.sinh,
    "cosh": math.cosh,
    "tanh": math.tanh,
    "float": float,
    "integer": _round,
    "round": _round,
    "truncate": math.trunc,
    "floor": math.floor,
    "ceiling": math.ceil,
    "float_integer_part": lambda a: float(math.trunc(a)),
    "float_fractional_part": lambda a: a - math.trunc(a),
    "\\": lambda a: ~int(_int_only("\\", lambda x, y: x)(a, 0)),
    "msb": lambda a: int(a).bit_length() - 1,
    "succ": lambda a: a + 1,
}

_CONSTANTS: dict[str, Number] = {
    "pi": math.pi,
    "e": math.e,
    "inf": math.inf,
    "infinite": math.inf,
    "nan": math.nan,
    "epsilon": 2.220446049250313e-16,
    "max_tagged_integer": (1 << 60) - 1,
}


BINARY_FUNCTIONS = frozenset(_BINARY)


def apply_binary(name: str, a: Number, b: Number) -> Number:
    """Apply binary function `name` to evaluated operands (for compiled clauses), as
    `evaluate` does, with the same ISO errors."""
    try:
        return _BINARY[name](a, b)
    except ZeroDivisionError as err:
        raise PrologEvaluationError("zero_divisor", f"{name}: division by zero") from err
    except (ValueError, OverflowError) as err:
        raise PrologEvaluationError("undefined", f"{name}/2: {err}") from err


def evaluate(t: Value) -> Number:
    """Evaluate an arithmetic expression; raise ISO errors for unbound or bad parts."""
    while type(t) is Var:
        if t.ref is None:
            raise PrologInstantiationError("arithmetic: an operand is unbound; bind it before is/2")
        t = t.ref
    tt = type(t)
    if tt is int or tt is float:
        return t
    if tt is Term:
        name, args = t[0], t[1]
        try:
            if len(args) == 2 and name in _BINARY:
                return _BINARY[name](evaluate(args[0]), evaluate(args[1]))
            if len(args) == 1 and name in _UNARY:
                fn = _UNARY[name]
                value = evaluate(args[0])
                return fn(value)
        except ZeroDivisionError as err:
            raise PrologEvaluationError("zero_divisor", f"{name}: division by zero") from err
        except (ValueError, OverflowError) as err:
            raise PrologEvaluationError("undefined", f"{name}/{len(args)}: {err}") from err
        if name == "." and len(args) == 2 and args[1] == "[]":
            return evaluate(args[0])
        culprit = Term("/", (name, len(args)))
        raise PrologTypeError(
            "evaluable", culprit, f"{name}/{len(args)} is not an arithmetic function"
        )
    if tt is str and t in _CONSTANTS:
        return _CONSTANTS[t]
    if tt is PString and len(t.text) == 1:
        return ord(t.text)
    if tt is str:
        culprit = Term("/", (t, 0))
        raise PrologTypeError("evaluable", culprit, f"{t}/0 is not an arithmetic function")
    raise PrologTypeError("evaluable", t, f"{t!r} is not a number or arithmetic expression")

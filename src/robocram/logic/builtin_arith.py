"""Arithmetic built-ins: `is/2` and the comparisons, over `arith.evaluate`."""

from __future__ import annotations

from collections.abc import Callable

from robocram.logic.arith import Number, evaluate
from robocram.logic.builtin_spec import Builtin, det
from robocram.logic.engine import DetFn, Engine
from robocram.logic.value import Value

__all__ = ["BUILTINS"]


def _is(m: Engine, args: tuple[Value, ...]) -> bool:
    return m.unify(args[0], evaluate(args[1]))


def _compare(op: Callable[[Number, Number], bool]) -> DetFn:
    def run(m: Engine, args: tuple[Value, ...]) -> bool:
        return op(evaluate(args[0]), evaluate(args[1]))

    return run


BUILTINS: tuple[Builtin, ...] = (
    det("is", _is, 2),
    det("<", _compare(lambda a, b: a < b), 2),
    det(">", _compare(lambda a, b: a > b), 2),
    det("=<", _compare(lambda a, b: a <= b), 2),
    det(">=", _compare(lambda a, b: a >= b), 2),
    det("=:=", _compare(lambda a, b: a == b), 2),
    det("=\\=", _compare(lambda a, b: a != b), 2),
)

"""Guards checked during head unification, before a later argument builds a term.

`qpart([X|L], Y, [X|L1], L2) :- X =< Y, !, ...` unifies its third argument (building
`[X|L1]` when the caller passed a variable) before the guard can fail. Once X and Y hold
integers, the guard's outcome cannot change any more: head unification only binds
variables. So the clause code tests it as soon as its values are known and skips the
building when it is false. Only a definite failure counts: a guard that would raise (an
unbound operand) or depend on a later binding is left to run in its place.
"""

from __future__ import annotations

from robocram.logic.template import Slot, Tmpl
from robocram.logic.terms import Term
from robocram.logic.value import Value

__all__ = ["guard_goals", "rejection"]

_COMPARE = {"<": "<", ">": ">", "=<": "<=", ">=": ">=", "=:=": "==", "=\\=": "!="}
_INT_OPS = {"+": "+", "-": "-", "*": "*"}
# When each ISO type test fails for a non-variable value `{0}` (already dereferenced)
_TYPE_FAILS = {
    "var": "True",
    "atom": "type({0}) is not str",
    "number": "type({0}) is not int and type({0}) is not float",
    "integer": "type({0}) is not int",
    "float": "type({0}) is not float",
    "atomic": "type({0}) is Term",
    "compound": "type({0}) is not Term",
    "callable": "type({0}) is not str and type({0}) is not Term",
}


def guard_goals(body: list[Value]) -> list[Value]:
    """The leading comparisons and type tests of a body (before any cut or binding goal)."""
    out = []
    for goal in body:
        if type(goal) is not Tmpl:
            break
        n = len(goal.args)
        if not (n == 2 and goal.name in _COMPARE or n == 1 and goal.name in _TYPE_FAILS):
            break
        out.append(goal)
    return out


def rejection(goal: Value) -> tuple[list[int], str] | None:
    """The slots of guard `goal` and a condition, on their dereferenced values, that holds
    only when the guard is certain to fail; None when there is no such cheap condition."""
    if len(goal.args) == 1:
        arg = goal.args[0]
        if type(arg) is not Slot:
            return None
        v = f"v{arg.i}"
        return [arg.i], f"type({v}) is not Var and {_TYPE_FAILS[goal.name].format(v)}"
    slots: list[int] = []
    left, right = _int_expr(goal.args[0], slots), _int_expr(goal.args[1], slots)
    if left is None or right is None or not slots:
        return None
    ints = " and ".join(f"type(v{i}) is int" for i in slots)
    return slots, f"{ints} and not ({left} {_COMPARE[goal.name]} {right})"


def _int_expr(t: Value, slots: list[int]) -> str | None:
    """Python for an expression of slots, integers, +, - and *; None for anything else."""
    if type(t) is Slot:
        if t.i not in slots:
            slots.append(t.i)
        return f"v{t.i}"
    if type(t) is int:
        return repr(t)
    if type(t) in (Tmpl, Term):
        name, args = (t.name, t.args) if type(t) is Tmpl else (t[0], t[1])
        if len(args) == 2 and name in _INT_OPS:
            a, b = _int_expr(args[0], slots), _int_expr(args[1], slots)
            if a is not None and b is not None:
                return f"({a} {_INT_OPS[name]} {b})"
    return None

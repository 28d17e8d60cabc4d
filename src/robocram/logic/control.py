"""Control constructs: conjunction, disjunction, if-then-else, soft-cut, negation, call/N,
once, ignore, catch/3 and the internal cut goals they expand into.

Each construct rewrites the continuation and may push a choicepoint; cut barriers make
`call/N`, `\\+` and the condition of `->` opaque to cut, while `,` and `;` are transparent.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from robocram.logic.choicepoints import (
    ALT,
    BARRIER,
    CATCH,
    CLAUSES,
    DEAD,
    GEN,
    PROC,
    REACT,
    ChoicePoint,
    Cont,
)
from robocram.logic.errors import PrologInstantiationError, PrologTypeError
from robocram.logic.terms import Term, Var, make_term
from robocram.logic.value import Value

if TYPE_CHECKING:
    from robocram.logic.engine import Engine

__all__ = ["ALT", "BARRIER", "CATCH", "CLAUSES", "CONTROL_NAMES", "DEAD", "FAIL", "GEN", "PROC"]
__all__ += ["REACT", "add_args", "run_control"]

FAIL = ("fail", 0, None)

CONTROL_NAMES: list[tuple[str, int]] = [
    (",", 2),
    (";", 2),
    ("->", 2),
    ("*->", 2),
    ("\\+", 1),
    ("not", 1),
    ("once", 1),
    ("ignore", 1),
    ("catch", 3),
    ("!", 0),
    ("true", 0),
    ("fail", 0),
    ("false", 0),
    ("$cut", 1),
    ("$softcut", 1),
    ("$exitcatch", 1),
] + [("call", n) for n in range(1, 9)]


def add_args(goal: Value, extra: tuple[Value, ...]) -> Value:
    """Append arguments to a callable term, as call/N does."""
    while type(goal) is Var:
        if goal.ref is None:
            raise PrologInstantiationError(
                "call/N: the goal is unbound; bind it to a callable term"
            )
        goal = goal.ref
    if type(goal) is str:
        return make_term((goal, extra)) if extra else goal
    if type(goal) is Term:
        return make_term((goal[0], goal[1] + extra)) if extra else goal
    raise PrologTypeError("callable", goal, f"call/N: {goal!r} is not a callable term")


def callable_body(goal: Value) -> Value:
    """Return `goal` after checking, as ISO's call/1 does, that its control tree is callable.

    `call((fail, 1))` raises `type_error(callable, (fail, 1))` before running anything.
    """
    stack = [goal]
    while stack:
        g = _deref(stack.pop())
        if type(g) is Term:
            if g[0] in _BODY_CONTROL and len(g[1]) == 2:
                stack.extend(g[1])
        elif type(g) is not str and type(g) is not Var:
            raise PrologTypeError("callable", goal, f"call/N: {goal!r} is not a callable goal")
    return goal


_BODY_CONTROL = frozenset([",", ";", "->", "*->"])


def _deref(t: Value) -> Value:
    while type(t) is Var and t.ref is not None:
        t = t.ref
    return t


def _cut(b: int) -> Term:
    return make_term(("$cut", (b,)))


def run_control(
    m: Engine, name: str, args: tuple[Value, ...], cutb: int, nxt: Cont, cps: list[ChoicePoint]
) -> Cont:
    """Execute one control construct; return the next continuation or FAIL."""
    trail = m.trail
    if name == ";":
        left = _deref(args[0])
        b = len(cps)
        if type(left) is Term and len(left[1]) == 2 and left[0] in ("->", "*->"):
            cps.append([ALT, len(trail), (args[1], cutb, nxt)])
            cond, then = left[1]
            marker = "$cut" if left[0] == "->" else "$softcut"
            return (cond, b + 1, (make_term((marker, (b,))), 0, (then, cutb, nxt)))
        cps.append([ALT, len(trail), (args[1], cutb, nxt)])
        return (left, cutb, nxt)
    if name == "$cut":
        del cps[args[0] :]
        return nxt
    if name == "call":
        return (callable_body(add_args(args[0], args[1:])), len(cps), nxt)
    if name == "->":
        b = len(cps)
        return (args[0], b, (_cut(b), 0, (args[1], cutb, nxt)))
    if name == "*->":
        return (args[0], len(cps), (args[1], cutb, nxt))
    if name == "$softcut":
        b = args[0]
        if b < len(cps) and cps[b][0] == ALT:
            cps[b] = [DEAD, cps[b][1]]
        return nxt
    if name in ("\\+", "not"):
        b = len(cps)
        cps.append([ALT, len(trail), nxt])
        return (args[0], b + 1, (_cut(b), 0, FAIL))
    if name == "once":
        b = len(cps)
        return (args[0], b, (_cut(b), 0, nxt))
    if name == "ignore":
        b = len(cps)
        cps.append([ALT, len(trail), nxt])
        return (args[0], b + 1, (_cut(b), 0, nxt))
    if name == "catch":
        b = len(cps)
        cps.append([CATCH, len(trail), args[1], args[2], nxt, cutb, True])
        return (args[0], b + 1, (make_term(("$exitcatch", (b,))), 0, nxt))
    if name == "$exitcatch":
        b = args[0]
        if b == len(cps) - 1:
            cps.pop()
        elif b < len(cps) and cps[b][0] == CATCH:
            cps[b][6] = False
            cps.append([REACT, len(trail), cps[b]])
        return nxt
    return _atom_control(name, cutb, nxt, cps)


def _atom_control(name: str, cutb: int, nxt: Cont, cps: list[ChoicePoint]) -> Cont:
    if name == "!":
        del cps[cutb:]
        return nxt
    if name == "true":
        return nxt
    return FAIL

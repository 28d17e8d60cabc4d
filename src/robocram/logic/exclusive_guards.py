"""Clauses whose arithmetic guards exclude each other need no choicepoint between them.

    tak(X, Y, Z, A) :- X =< Y, Z = A.
    tak(X, Y, Z, A) :- X > Y, ...

Once the first clause's `X =< Y` has held, the second clause's `X > Y` must fail for
the same call arguments, so a procedure that got past the first clause's guards need
not leave a choicepoint for the second. A guard counts when it leads the body (only
cuts and other such guards before it, all run inline before the clause exits) and
compares call arguments (head arguments that are plain variables) or integers, and
the first clause's head is distinct variables, so that it binds nothing the later
clause would have seen unbound (the later clause would then raise, not fail).
"""

from __future__ import annotations

from typing import Protocol

from robocram.logic.template import Slot, Tmpl
from robocram.logic.value import Value

__all__ = ["excludes"]

Operand = tuple[str, int]  # ("arg", position) or ("int", value)
Guard = tuple[str, Operand, Operand]
_NEGATION = {"=<": ">", ">": "=<", "<": ">=", ">=": "<", "=:=": "=\\=", "=\\=": "=:="}
_SWAPPED = {"<": ">", ">": "<", "=<": ">=", ">=": "=<", "=:=": "=:=", "=\\=": "=\\="}


class _Clause(Protocol):
    head: tuple[Value, ...]
    body_rev: tuple[Value, ...]


def excludes(first: _Clause, later: _Clause) -> bool:
    """True when `later` must fail on every call for which `first`'s leading guards held.

    >>> from robocram.logic.template import Slot, Tmpl
    >>> x, y = Slot(0), Slot(1)
    >>> class C:
    ...     def __init__(self, op): self.head, self.body_rev = (x, y), (Tmpl(op, (x, y)),)
    >>> excludes(C("=<"), C(">")), excludes(C("=<"), C(">="))
    (True, False)
    """
    if not _binds_nothing(first):
        return False  # its head may bind call variables that `later` would see unbound
    held = _guards(first)
    if not held:
        return False
    for op, a, b in _guards(later):
        for op1, a1, b1 in held:
            negated = _NEGATION[op1]
            if (op, a, b) == (negated, a1, b1) or (op, a, b) == (_SWAPPED[negated], b1, a1):
                return True
    return False


def _binds_nothing(clause: _Clause) -> bool:
    """True when the head is distinct variables: unifying it binds no call variable."""
    seen: set[int] = set()
    for p in clause.head:
        if type(p) is not Slot or p.i in seen:
            return False
        seen.add(p.i)
    return True


def _guards(clause: _Clause) -> list[Guard]:
    """The comparisons leading the clause body, on call arguments and integers."""
    positions: dict[int, int] = {}
    for k, p in enumerate(clause.head):
        if type(p) is Slot:
            positions.setdefault(p.i, k)
    out: list[Guard] = []
    for goal in reversed(clause.body_rev):
        if goal == "!":
            continue
        if type(goal) is not Tmpl or goal.name not in _NEGATION or len(goal.args) != 2:
            break
        a, b = (_operand(x, positions) for x in goal.args)
        if a is None or b is None:
            break
        out.append((goal.name, a, b))
    return out


def _operand(t: Value, positions: dict[int, int]) -> Operand | None:
    if type(t) is Slot:
        k = positions.get(t.i)
        return None if k is None else ("arg", k)
    if type(t) is int:
        return ("int", t)
    return None

"""Whether a term is cyclic (`X = f(X)`): the test the cycle-safe walkers share.

Kept apart from cycles.py (which raises the error) so that term conversion can use it
without importing the error classes.
"""

from __future__ import annotations

from robocram.logic.terms import Term, Var
from robocram.logic.value import Value

__all__ = ["is_acyclic"]


def is_acyclic(t: Value) -> bool:
    """True unless following bindings from `t` leads back into a compound on the path."""
    on_path: set[int] = set()
    done: set[int] = set()
    stack: list[tuple[Value, bool]] = [(t, False)]
    while stack:
        t, leaving = stack.pop()
        if leaving:
            on_path.discard(id(t))
            done.add(id(t))
            continue
        while type(t) is Var and t.ref is not None:
            t = t.ref
        if type(t) is not Term or id(t) in done:
            continue
        if id(t) in on_path:
            return False
        on_path.add(id(t))
        stack.append((t, True))
        stack.extend((arg, False) for arg in t[1])
    return True

"""A clause body as ISO stores it: variable goals become `call(G)`, leaves are callable.

ISO converts a body term before storing it (7.6.2): a variable in a control position
(`,`, `;`, `->`, and, as SWI-Prolog does, `*->` and `\\+`) becomes `call(V)`, so
`clause/2` gives it back wrapped; a number there is `type_error(callable, Body)`.
"""

from __future__ import annotations

from robocram.logic.errors import PrologTypeError
from robocram.logic.terms import PString, Term, Var, deref
from robocram.logic.value import Value

__all__ = ["stored_body"]

_CONTROL = frozenset([(",", 2), (";", 2), ("->", 2), ("*->", 2), ("\\+", 1)])


def stored_body(body: Value) -> Value:
    """Return `body` with its variable goals wrapped in call/1; raise if a goal is a number.

    >>> v = Var(); stored_body(Term(",", (v, "true")))[1][0][0]
    'call'
    """
    if type(body) is str:  # a fact's `true`, or one atom goal: nothing to wrap
        return body
    out: list[Value] = []
    stack: list[tuple[bool, Value]] = [(False, body)]
    changed = False
    while stack:
        built, g = stack.pop()
        if built:  # the arguments of control construct g are on `out`
            n = len(g[1])
            args = tuple(out[len(out) - n :])
            del out[len(out) - n :]
            out.append(Term(g[0], args) if args != g[1] else g)
            continue
        g = deref(g)
        if type(g) is Var:
            out.append(Term("call", (g,)))
            changed = True
        elif type(g) is Term and (g[0], len(g[1])) in _CONTROL:
            stack.append((True, g))
            stack.extend((False, a) for a in reversed(g[1]))
        elif type(g) in (int, float, PString):
            raise PrologTypeError(
                "callable", body, f"clause body {body!r} has a goal {g!r} that is not callable"
            )
        else:
            out.append(g)
    return out[0] if changed else body

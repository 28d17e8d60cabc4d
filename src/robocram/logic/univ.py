"""`=../2` ("univ") both ways, shared by the built-in and by compiled clause code.

>>> univ_list(Term("f", ("a", 1)))
[f,a,1]
>>> univ_compose(univ_list(Term("f", ("a", 1))))
f(a,1)
"""

from __future__ import annotations

from robocram.logic.errors import PrologDomainError, PrologInstantiationError, PrologTypeError
from robocram.logic.terms import NIL, Term, Var, make_term
from robocram.logic.value import Value

__all__ = ["univ_compose", "univ_list"]


def univ_list(t: Value) -> Value:
    """The list `[Name|Args]` of term `t` (`[t]` for an atomic one); None when unbound."""
    while type(t) is Var:
        r = t.ref
        if r is None:
            return None
        t = r
    if type(t) is not Term:
        return make_term((".", (t, NIL)))
    items: Value = NIL
    args = t[1]
    for i in range(len(args) - 1, -1, -1):
        items = make_term((".", (args[i], items)))
    return make_term((".", (t[0], items)))


def univ_compose(items: Value) -> Value:
    """The term that list `items` describes (`[Name|Args]`), with ISO's errors."""
    parts: list[Value] = []
    t = items
    while True:
        while type(t) is Var and t.ref is not None:
            t = t.ref
        if type(t) is not Term or t[0] != "." or len(t[1]) != 2:
            break
        parts.append(t[1][0])
        t = t[1][1]
    if type(t) is Var:
        raise PrologInstantiationError("=../2: the list is partial (ends in a variable)")
    if t != NIL or type(t) is not str:
        raise PrologTypeError("list", t, f"=../2: expected a list, got {t!r}")
    if not parts:
        raise PrologDomainError("non_empty_list", NIL, "=../2: the list is empty")
    head = parts[0]
    while type(head) is Var and head.ref is not None:
        head = head.ref
    if len(parts) == 1:
        return head
    if type(head) is not str:
        raise PrologTypeError("atom", head, f"=../2: {head!r} cannot name a compound")
    return make_term((head, tuple(parts[1:])))

"""Compile clause terms into stored `Clause` objects keyed by name/arity."""

from __future__ import annotations

from robocram.logic.clause import Clause
from robocram.logic.clause_body import stored_body
from robocram.logic.errors import PrologInstantiationError, PrologTypeError
from robocram.logic.keys import pred_key
from robocram.logic.template import Slot, compile_term
from robocram.logic.terms import Term, Var, deref
from robocram.logic.unify import copy_resolved
from robocram.logic.value import Value

__all__ = ["compile_clause", "conjuncts", "parse_indicator"]


def conjuncts(body: Value) -> list[Value]:
    """Flatten a conjunction into its goals; a variable goal becomes call(Var)."""
    goals: list[Value] = []
    stack = [body]
    while stack:
        g = deref(stack.pop())
        if type(g) is Term and g[0] == "," and len(g[1]) == 2:
            stack.append(g[1][1])
            stack.append(g[1][0])
        elif type(g) is Var:
            goals.append(Term("call", (g,)))
        elif type(g) in (int, float):
            raise PrologTypeError("callable", g, f"clause body goal {g!r} is a number, not a goal")
        elif g != "true":
            goals.append(g)
    return goals


def compile_clause(
    term: Value, group: str | None, shared_key: bool = True
) -> tuple[tuple[str, int], Clause]:
    """Compile `Head :- Body` (or a fact) into a Clause; return its name/arity key too.

    The key is the shared object (keys.py) unless `shared_key` is false: assert/1 looks
    its predicate up with a plain tuple and takes the shared key only when it creates one.

    >>> from robocram.logic.reader import read_query
    >>> key, clause = compile_clause(read_query("p(X, Y) :- q(X), r(Y)")[0], "g")
    >>> key, clause.nvars, len(clause.body_rev)
    (('p', 2), 2, 2)
    """
    term = copy_resolved(term)
    if type(term) is Term and term[0] == ":-" and len(term[1]) == 2:
        head, body = deref(term[1][0]), term[1][1]
    else:
        head, body = term, "true"
    new_body = stored_body(body)
    if new_body is not body:
        body = new_body
        term = Term(":-", (head, body))
    if type(head) is Var:
        raise PrologInstantiationError("clause head is an unbound variable; write name(Args...)")
    args: tuple[Value, ...]
    if type(head) is str:
        name, args = head, ()
    elif type(head) is Term:
        name, args = head[0], head[1]
    else:
        raise PrologTypeError(
            "callable", head, f"clause head {head!r} is not an atom or compound term"
        )
    slots: dict[Var, Slot] = {}
    head_t = tuple([compile_term(a, slots) for a in args])
    # a fact (asserted facts by the thousand: sieve) has no goals to flatten
    body_t = (
        []
        if type(body) is str and body == "true"
        else [compile_term(g, slots) for g in conjuncts(body)]
    )
    clause = Clause(head_t, tuple(reversed(body_t)), len(slots), group, term, name)
    return (pred_key(name, len(args)) if shared_key else (name, len(args))), clause


def parse_indicator(spec: Value) -> tuple[str, int]:
    """Read `name/arity` (a Term or the text 'name/arity') into a key."""
    spec = deref(spec)
    if isinstance(spec, str) and "/" in spec:
        name, _, arity = spec.rpartition("/")
        if arity.isdigit() and name:
            return name, int(arity)
    if type(spec) is Term and spec[0] == "/" and len(spec[1]) == 2:
        name, arity = deref(spec[1][0]), deref(spec[1][1])
        if type(name) is str and type(arity) is int:
            return name, arity
    raise PrologTypeError(
        "predicate_indicator", spec, f"{spec!r} is not a predicate indicator name/arity"
    )

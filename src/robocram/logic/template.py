"""Clause templates: terms whose variables are numbered slots, and building them.

A stored clause is renamed apart by building its templates against a fresh register list,
so the stored templates are never mutated and can be shared by concurrent queries.
"""

from __future__ import annotations

from robocram.logic.terms import Term, Var, make_term, make_var
from robocram.logic.unify import unify
from robocram.logic.value import Value

__all__ = ["Slot", "Tmpl", "build", "compile_term", "index_key_of_template", "unify_head"]


class Slot:
    """The i-th variable of a clause template."""

    __slots__ = ("i",)

    def __init__(self, i: int) -> None:
        self.i = i


class Tmpl:
    """A compound template that contains at least one Slot."""

    __slots__ = ("args", "name")

    def __init__(self, name: str, args: tuple[Value, ...]) -> None:
        self.name = name
        self.args = args


def index_key_of_template(t: Value) -> Value:
    """Return the first-argument index key of a template (None for a variable)."""
    if type(t) is Slot:
        return None
    if type(t) is Tmpl:
        return (t.name, len(t.args))
    if type(t) is Term:
        return (t[0], len(t[1]))
    try:
        hash(t)
    except TypeError:
        return None
    return t


def compile_term(term: Value, slots: dict[Var, Slot]) -> Value:
    """Turn a term into a template, numbering its unbound variables in `slots`."""
    while type(term) is Var:
        if term.ref is None:
            slot = slots.get(term)
            if slot is None:
                slot = slots[term] = Slot(len(slots))
            return slot
        term = term.ref
    if type(term) is not Term:
        return term
    args = tuple([compile_term(a, slots) for a in term[1]])
    if any(type(a) is Slot or type(a) is Tmpl for a in args):
        return Tmpl(term[0], args)
    return make_term((term[0], args))


def build(t: Value, regs: list[Value]) -> Value:
    """Instantiate a template against the registers, creating fresh Vars on first use."""
    tt = type(t)
    if tt is Slot:
        v = regs[t.i]
        if v is None:  # make_var and the slot set here: no Python frame to run
            v = regs[t.i] = make_var()
            v.ref = None
        return v
    if tt is Tmpl:
        return make_term((t.name, tuple([build(a, regs) for a in t.args])))
    return t


def unify_head(p: Value, t: Value, regs: list[Value], trail: list[Var]) -> bool:
    """Unify head template `p` with call argument `t` without building the head first."""
    tp = type(p)
    if tp is Slot:
        v = regs[p.i]
        if v is None:
            regs[p.i] = t
            return True
        return unify(v, t, trail)
    while type(t) is Var:
        r = t.ref
        if r is None:
            t.ref = build(p, regs)
            trail.append(t)
            return True
        t = r
    if tp is Tmpl:
        if type(t) is not Term or t[0] != p.name:
            return False
        targs = t[1]
        pargs = p.args
        if len(targs) != len(pargs):
            return False
        return all(unify_head(pargs[i], targs[i], regs, trail) for i in range(len(pargs)))
    if type(t) is type(p) and type(p) is not Term:
        return bool(t == p)
    return unify(p, t, trail)

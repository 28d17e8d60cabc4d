"""Compiled clauses: head and body templates whose variables are numbered slots.

A clause is renamed apart by building its templates against a fresh register list, so the
stored clause is never mutated and can be shared by concurrent queries.
"""

from __future__ import annotations

from typing import Any

from robocram.logic.terms import Term, Var, new_term
from robocram.logic.unify import unify

__all__ = ["Clause", "Slot", "Tmpl", "build", "compile_term", "unify_head"]

_COMPILE_AFTER = 2


class Slot:
    """The i-th variable of a clause template."""

    __slots__ = ("i",)

    def __init__(self, i: int) -> None:
        self.i = i


class Tmpl:
    """A compound template that contains at least one Slot."""

    __slots__ = ("args", "name")

    def __init__(self, name: str, args: tuple[Any, ...]) -> None:
        self.name = name
        self.args = args


class Clause:
    """A stored clause: head argument templates, body goal templates (reversed), var count.

    `run` is the clause's specialised function (see codegen), made on the second call so
    that facts looked up once (a big fact table) never pay for code generation.
    """

    __slots__ = ("body_rev", "calls", "group", "head", "key", "name", "nvars", "run", "source")

    def __init__(
        self,
        head: tuple[Any, ...],
        body_rev: tuple[Any, ...],
        nvars: int,
        group: str | None,
        source: Any,
        name: str = "",
    ) -> None:
        self.head = head
        self.body_rev = body_rev
        self.nvars = nvars
        self.group = group
        self.source = source
        self.name = name
        self.key = index_key_of_template(head[0]) if head else None
        self.run: Any = None
        self.calls = 0

    def prepare(self) -> Any:
        """Return the function to run this clause with: interpreted first, then compiled."""
        self.calls += 1
        if self.calls < _COMPILE_AFTER:
            return self.interpret
        from robocram.logic.codegen import compile_clause_fn

        try:
            self.run = compile_clause_fn(self)
        except (SyntaxError, RecursionError, MemoryError):
            # Too deeply nested for Python's compiler (e.g. a head with a 150-element
            # list): interpreting it is correct, only slower.
            self.run = self.interpret
        return self.run

    def interpret(
        self, args: tuple[Any, ...], trail: list[Var], cb: int, nxt: Any, cps: list[list[Any]]
    ) -> Any:
        """Unify the head with `args` and return the body's continuation (False on failure)."""
        regs: list[Any] = [None] * self.nvars
        head = self.head
        for i in range(len(head)):
            if not unify_head(head[i], args[i], regs, trail):
                return False
        cont = nxt
        for g in self.body_rev:
            cont = (build(g, regs), cb, cont)
        return cont


def index_key_of_template(t: Any) -> Any:
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


def compile_term(term: Any, slots: dict[Var, Slot]) -> Any:
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
    return new_term(Term, (term[0], args))


def build(t: Any, regs: list[Any]) -> Any:
    """Instantiate a template against the registers, creating fresh Vars on first use."""
    tt = type(t)
    if tt is Slot:
        v = regs[t.i]
        if v is None:
            v = regs[t.i] = Var()
        return v
    if tt is Tmpl:
        return new_term(Term, (t.name, tuple([build(a, regs) for a in t.args])))
    return t


def unify_head(p: Any, t: Any, regs: list[Any], trail: list[Var]) -> bool:
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

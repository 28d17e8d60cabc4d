"""Compiled clauses: head and body templates, interpreted first and then generated code.

A clause is renamed apart by building its templates against a fresh register list, so the
stored clause is never mutated and can be shared by concurrent queries.
"""

from __future__ import annotations

from robocram.logic.choicepoints import ChoicePoint, Cont
from robocram.logic.codegen import ClauseFn, compile_clause_fn
from robocram.logic.occurs import unify_checked
from robocram.logic.shared_code import shared_clause_fn
from robocram.logic.template import build, index_key_of_template, unify_head
from robocram.logic.terms import Var
from robocram.logic.value import Value

__all__ = ["Clause"]

_COMPILE_AFTER = 2


class Clause:
    """A stored clause: head argument templates, body goal templates (reversed), var count.

    `run` is the clause's specialised function (see codegen), made on the second call so
    that facts looked up once (a big fact table) never pay for code generation.
    """

    __slots__ = (
        "body_rev",
        "calls",
        "erased",
        "group",
        "head",
        "key",
        "name",
        "nvars",
        "run",
        "source",
    )

    def __init__(
        self,
        head: tuple[Value, ...],
        body_rev: tuple[Value, ...],
        nvars: int,
        group: str | None,
        source: Value,
        name: str = "",
    ) -> None:
        self.head = head
        self.body_rev = body_rev
        self.nvars = nvars
        self.group = group
        self.source = source
        self.name = name
        self.key = index_key_of_template(head[0]) if head else None
        self.run: ClauseFn | None = None
        self.calls = 0
        self.erased = False  # retracted; calls that started before still see it

    def prepare(self) -> ClauseFn:
        """Return the function to run this clause with: interpreted first, then compiled."""
        self.calls += 1
        if self.calls < _COMPILE_AFTER:
            return self.interpret
        try:
            # a loaded clause's templates may be another knowledge base's too (shared_reads)
            self.run = compile_clause_fn(self) if self.group is None else shared_clause_fn(self)
        except (SyntaxError, RecursionError, MemoryError):
            # Too deeply nested for Python's compiler (e.g. a head with a 150-element
            # list): interpreting it is correct, only slower.
            self.run = self.interpret
        return self.run

    def interpret(
        self, args: tuple[Value, ...], trail: list[Var], cb: int, nxt: Cont, cps: list[ChoicePoint]
    ) -> Cont:
        """Unify the head with `args` and return the body's continuation (False on failure)."""
        regs: list[Value] = [None] * self.nvars
        head = self.head
        for i in range(len(head)):
            if not unify_head(head[i], args[i], regs, trail):
                return False
        return self.body(regs, cb, nxt)

    def body(self, regs: list[Value], cb: int, nxt: Cont) -> Cont:
        """The continuation running the body goals built against `regs`, then `nxt`."""
        cont = nxt
        for g in self.body_rev:
            cont = (build(g, regs), cb, cont)
        return cont

    def interpret_checked(
        self,
        args: tuple[Value, ...],
        trail: list[Var],
        cb: int,
        nxt: Cont,
        cps: list[ChoicePoint],
        error: bool = False,
    ) -> Cont:
        """`interpret` with the occurs check in head unification (flag true or error)."""
        regs: list[Value] = [None] * self.nvars
        head = self.head
        for i in range(len(head)):
            if not unify_checked(build(head[i], regs), args[i], trail, error):
                return False
        return self.body(regs, cb, nxt)

    def interpret_error(
        self, args: tuple[Value, ...], trail: list[Var], cb: int, nxt: Cont, cps: list[ChoicePoint]
    ) -> Cont:
        """`interpret_checked` raising on a cyclic binding (flag error)."""
        return self.interpret_checked(args, trail, cb, nxt, cps, error=True)

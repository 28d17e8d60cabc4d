"""Compile a static predicate into one Python function that tries its clauses in order.

Running clause by clause through the machine costs a choicepoint per call of a predicate
with two or more clauses, and a trip round the goal dispatch per clause tried. The
generated procedure instead runs each clause's head unification and leading inline
built-ins (comparisons, `is/2`, `=/2`, cut) in one frame, undoing the trail and falling
through to the next clause when one fails there ("shallow backtracking"). It pushes a
choicepoint only when a clause has got past those and a later clause can still match
the first argument; a cut among them commits to the clause, so `tak/4`, `p_remove/3`
or `d/3` of deriv never make one. A clause ending in a call to the predicate itself
loops in the same frame.

    proc(args, trail, nxt, cps, start) -> continuation, or False when no clause from
        `start` on gets past its inline goals; or the argument list plus one extra item
        after CHECK_EVERY loops, so that the machine counts them and calls again

The first argument is switched on before any clause runs: two dictionaries give the
first and the last clause whose first argument can match its principal functor or
constant, so clauses before the first are skipped and no choicepoint is left after
the last.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from robocram.logic.choicepoints import PROC
from robocram.logic.codegen import ClauseCode, ClauseWriter, make_factory
from robocram.logic.limits import CHECK_EVERY
from robocram.logic.template import Tmpl
from robocram.logic.terms import Term

__all__ = ["MAX_CLAUSES", "Procedure", "compile_procedure"]

Procedure = Callable[[Any, list[Any], Any, list[list[Any]], int], Any]
MAX_CLAUSES = 64
Tables = tuple[dict[Any, int], dict[Any, int]]  # first and last clause per key
_CHAIN_KEYS = 4  # up to this many keys, switch by comparisons; beyond, by dictionaries


class _Maybe:
    """The switch key of a call whose first argument is unbound or not indexable."""

    def __repr__(self) -> str:
        return "MAYBE"


MAYBE = _Maybe()


def compile_procedure(stored: Sequence[ClauseCode]) -> Procedure | None:
    """Return the procedure of a static predicate's clauses, or None when not worth it."""
    clauses = list(stored)
    if not 1 <= len(clauses) <= MAX_CLAUSES:
        return None
    try:
        writer = _ProcWriter(len(clauses[0].head))
        writer.procedure(clauses)
        params = ", ".join(f"k{i}" for i in range(len(writer.consts)))
        source = "\n".join(
            [f"def make({params}):", "  def proc(args, trail, nxt, cps, start):", *writer.lines]
            + ["  return proc", ""]
        )
        proc: Procedure = make_factory(source)(*writer.consts)
    except (SyntaxError, RecursionError, MemoryError):
        return None  # too deeply nested to compile; the clauses run one by one instead
    return proc


def switch_key(t: Any) -> Any:
    """The key a head argument is switched on: a functor's name, a constant, or MAYBE."""
    if type(t) is Tmpl:
        return t.name
    if type(t) is Term:
        return t[0]
    if type(t) is str or type(t) is int:
        return t
    return MAYBE  # a variable, a float (1.0 = 1 in Python) or an opaque constant


def switch_tables(clauses: list[ClauseCode]) -> Tables:
    """First and last clause index that each key can match (MAYBE: all of them)."""
    keys = [switch_key(c.head[0]) for c in clauses]
    open_at = [i for i, k in enumerate(keys) if k is MAYBE]
    first: dict[Any, int] = {MAYBE: 0}
    last: dict[Any, int] = {MAYBE: len(clauses) - 1}
    for i, k in enumerate(keys):
        if k is not MAYBE:
            first.setdefault(k, min([i, *open_at]))
            last[k] = max([i, *open_at])
    # a key no clause names: only the clauses with a variable there can match
    first[None] = open_at[0] if open_at else len(clauses)
    last[None] = open_at[-1] if open_at else -1
    return first, last


def _name(t: Any) -> str | None:
    """The functor name of a compound head argument; None for anything else."""
    if type(t) is Tmpl:
        return t.name
    return t[0] if type(t) is Term else None


class _ProcWriter(ClauseWriter):
    """Writes the clause-by-clause procedure; failing inline goals fall to the next clause."""

    def __init__(self, arity: int) -> None:
        super().__init__()
        self.arity = arity
        self.index = 0
        self.committed = False

    def procedure(self, clauses: list[ClauseCode]) -> None:
        names = "".join(f"a{i}, " for i in range(self.arity))
        if self.arity:
            self.emit(f"{names}= args", 1)
        self.emit("steps = 0", 1)
        self.emit("while True:", 1)
        self.emit("if not cps and trail: del trail[:]", 2)
        # Hand a long self-recursion back to the machine now and then, so that it counts
        # the inferences (limits, stop requests), and it calls the procedure again.
        self.emit("steps += 1", 2)
        self.emit(f"if steps >= {CHECK_EVERY}: return [{names}None]", 2)
        self.emit("cb = len(cps)", 2)
        self.emit("mark = len(trail)", 2)
        self.switch(clauses)
        for i, clause in enumerate(clauses):
            self.index = i
            self.committed = False
            self.fail = "break"
            self.emit(f"if start <= {i} <= last:", 2)
            self.emit("while True:", 3)
            self.base = 3
            self.clause_code(clause)
            self.base = 0
            self.emit("if start < 0: start = 0; continue", 3)
            self.emit("while len(trail) > mark: trail.pop().ref = None", 3)
        self.emit("return False", 2)

    def switch(self, clauses: list[ClauseCode]) -> None:
        """Emit the first-argument switch setting `start` and `last`."""
        if not self.arity:
            self.emit(f"last = {len(clauses) - 1}", 2)
            return
        first, last = switch_tables(clauses)
        unknown = (first.pop(None), last.pop(None))
        every = (first.pop(MAYBE), last.pop(MAYBE))
        self.emit("x = a0", 2)
        self.emit("while type(x) is Var and x.ref is not None: x = x.ref", 2)
        self.emit("a0 = x", 2)
        self.emit("t = type(x)", 2)
        if len(first) > _CHAIN_KEYS:
            self.emit("if t is Term: x = x[0]", 2)
            self.emit("elif t is not str and t is not int: x = None", 2)
            self.emit(f"if x is None: i, last = {every[0]}, {every[1]}", 2)
            self.emit(f"else: i, last = {self.const(first)}.get(x, {unknown[0]}), ", 2)
            self.lines[-1] += f"{self.const(last)}.get(x, {unknown[1]})"
        else:
            heads = [c.head[0] for c in clauses]
            compound = {_name(h) for h in heads} - {None}
            atomic = {h for h in heads if type(h) is str or type(h) is int}
            self.emit("if t is Term:", 2)
            self.emit("x = x[0]", 3)
            self.chain(compound, (first, last), unknown)
            self.emit("elif t is str or t is int:", 2)
            self.chain(atomic, (first, last), unknown)
            self.emit(f"else: i, last = {every[0]}, {every[1]}", 2)
        self.emit("if start < i: start = i", 2)

    def chain(self, keys: set[Any], tables: Tables, unknown: tuple[int, int]) -> None:
        """Emit comparisons of `x` with each key, setting `i` and `last`."""
        first, last = tables
        branch = "if"
        for k in first:
            if k in keys:
                self.emit(f"{branch} x == {self.const(k)}: i, last = {first[k]}, {last[k]}", 3)
                branch = "elif"
        otherwise = "else: " if branch == "elif" else ""
        self.emit(f"{otherwise}i, last = {unknown[0]}, {unknown[1]}", 3)

    def cut(self) -> None:
        # No choicepoint was made since the clause began: committing means pushing none
        # for the later clauses, and failing from here on fails the whole call.
        self.committed = True
        self.fail = "return False"

    def alternatives(self) -> None:
        """Emit the choicepoint for the later clauses, unless cut or none can match."""
        if self.committed:
            return
        names = "".join(f"a{i}, " for i in range(self.arity))
        i = self.index
        self.emit(f"if last > {i}: cps.append([{PROC}, mark, ({names}), nxt, proc, {i + 1}])", 1)

    def exit(self, cont: str) -> None:
        self.alternatives()
        self.emit(f"return {cont}", 1)

    def self_call(self, args: str) -> None:
        self.alternatives()
        self.emit(f"{''.join(f'a{i}, ' for i in range(self.arity))}= {args}", 1)
        self.emit("start = -1; break", 1)

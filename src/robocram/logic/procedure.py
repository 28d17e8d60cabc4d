"""Compile a small deterministic predicate into one switching Python function.

When every clause of a predicate has a distinct constant or functor in the same argument
position, at most one clause can match a call that binds that argument, so no choicepoint
is needed. The generated procedure switches on that argument, runs the matching clause's
code inline, and runs a call to the predicate itself (the recursive clause of `app/3`,
`no_attack/3` of 8-queens) as a loop in the same Python frame:

    proc(args, trail, nxt, cps) -> continuation, False (no clause matches or it fails),
                                   or the argument list when the switch argument is
                                   unbound (the machine then tries the clauses in order);
                                   the list has one extra item after CHECK_EVERY loops,
                                   so that the machine counts them

Skipping the clauses that cannot match changes no answer: they would fail in their head.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from robocram.logic.codegen import ClauseCode, ClauseWriter, make_factory
from robocram.logic.limits import CHECK_EVERY
from robocram.logic.template import Tmpl
from robocram.logic.terms import Term

__all__ = ["MAX_CLAUSES", "Procedure", "compile_procedure"]

Procedure = Callable[[tuple[Any, ...], list[Any], Any, list[list[Any]]], Any]
MAX_CLAUSES = 8
_ATOMIC = (str, int, float)


def compile_procedure(stored: Sequence[ClauseCode]) -> Procedure | None:
    """Return the switching procedure of a static predicate's clauses, or None."""
    clauses = list(stored)
    if not 2 <= len(clauses) <= MAX_CLAUSES:
        return None
    position = _switch_position(clauses)
    if position is None:
        return None
    try:
        writer = _write_switch(clauses, position)
        params = ", ".join(f"k{i}" for i in range(len(writer.consts)))
        source = "\n".join(
            [f"def make({params}):", "  def proc(args, trail, nxt, cps):", *writer.lines]
            + ["  return proc", ""]
        )
        proc: Procedure = make_factory(source)(*writer.consts)
    except (SyntaxError, RecursionError, MemoryError):
        return None  # too deeply nested to compile; the clauses run one by one instead
    return proc


def _write_switch(clauses: list[ClauseCode], position: int) -> ClauseWriter:
    """Emit the loop that switches on argument `position` into each clause's code."""
    writer = ClauseWriter()
    arity = len(clauses[0].head)
    a = f"a{position}"
    writer.emit("".join(f"a{i}, " for i in range(arity)) + "= args", 1)
    writer.emit("steps = 0", 1)
    writer.emit("while True:", 1)
    writer.emit("if not cps and trail: del trail[:]", 2)
    # Hand a long self-recursion back to the machine now and then, so that it counts the
    # inferences (limits, stop requests); the machine then runs the clauses itself.
    writer.emit("steps += 1", 2)
    bail = "".join(f"a{i}, " for i in range(arity)) + "None"
    writer.emit(f"if steps >= {CHECK_EVERY}: return [{bail}]", 2)
    writer.emit("cb = len(cps)", 2)
    writer.emit(f"while type({a}) is Var and {a}.ref is not None: {a} = {a}.ref", 2)
    writer.emit(f"ta = type({a})", 2)
    writer.emit(f"if ta is Var: return [{''.join(f'a{i}, ' for i in range(arity))}]", 2)
    compound = [c for c in clauses if _is_compound(c.head[position])]
    if compound:
        writer.emit("if ta is Term:", 2)
        writer.emit(f"fn = {a}[0]; fa = len({a}[1])", 3)
        for c in compound:
            name, args = _functor(c.head[position])
            writer.emit(f"if fn == {writer.const(name)} and fa == {len(args)}:", 3)
            _clause_at(writer, c, 4, position)
        writer.emit("return False", 3)
    for c in clauses:
        key = c.head[position]
        if not _is_compound(key):
            test = f"ta is {type(key).__name__} and {a} == {writer.const(key)}"
            writer.emit(f"if {test}:", 2)
            _clause_at(writer, c, 3, position)
    writer.emit("return False", 2)
    return writer


def _clause_at(writer: ClauseWriter, clause: ClauseCode, depth: int, position: int) -> None:
    writer.base = depth - 1
    writer.clause_code(clause, loop=True, switched=position)
    writer.base = 0


def _is_compound(t: Any) -> bool:
    return type(t) is Tmpl or type(t) is Term


def _functor(t: Any) -> tuple[str, tuple[Any, ...]]:
    return (t.name, t.args) if type(t) is Tmpl else (t[0], t[1])


def _switch_position(clauses: list[ClauseCode]) -> int | None:
    """The first argument where every clause has a distinct constant or functor."""
    for i in range(len(clauses[0].head)):
        keys: list[Any] = []
        for c in clauses:
            t = c.head[i]
            if _is_compound(t):
                name, args = _functor(t)
                keys.append(("$functor", name, len(args)))
            elif type(t) in _ATOMIC and t == t:
                keys.append(t)
            else:
                break
        else:
            if len(set(keys)) == len(keys):
                return i
    return None

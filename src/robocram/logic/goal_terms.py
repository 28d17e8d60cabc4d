"""Inline code for `arg/3` and `functor/3` in clause bodies (boyer's rewrite loop).

Called as built-ins they cost a dispatch each; inline, the common cases are a few
tuple reads: `arg(N, T, A)` with N an integer in range and T compound, `functor(T, F, N)`
taking T apart, or building it when T is a fresh variable. Every other case calls the
checks of functor_arg.py, which raise the ISO error or let the goal fail.
"""

from __future__ import annotations

from typing import Protocol

from robocram.logic.template import Slot, Tmpl
from robocram.logic.value import Value

__all__ = ["TERM_GOALS", "emit_term_goal"]

TERM_GOALS = frozenset([("arg", 3), ("functor", 3)])


class GoalWriter(Protocol):
    """What these emitters use of goal_writer.GoalWriter."""

    known: set[int]
    fail: str

    def emit(self, line: str, depth: int) -> None: ...

    def temp(self) -> str: ...

    def const(self, value: Value) -> str: ...

    def build(self, t: Value) -> str: ...

    def unify_arg(self, p: Value, x: str, depth: int) -> None: ...


def emit_term_goal(w: GoalWriter, name: str, args: tuple[Value, ...]) -> bool:
    """Emit `name(args...)` inline; False when it cannot be (an argument is a fresh slot)."""
    if name == "arg":
        return _arg(w, *args)
    return _functor(w, *args)


def _value(w: GoalWriter, t: Value) -> str | None:
    """A Python expression for template `t`; None if it holds a slot not yet bound."""
    if type(t) is Slot:
        return f"v{t.i}" if t.i in w.known else None
    if type(t) is Tmpl:
        found: list[int] = []
        _slots(t, found)
        return w.build(t) if all(i in w.known for i in found) else None
    return w.const(t)


def _slots(t: Value, out: list[int]) -> None:
    if type(t) is Slot:
        out.append(t.i)
    elif type(t) is Tmpl:
        for a in t.args:
            _slots(a, out)


def _deref(x: str) -> str:
    return f"while type({x}) is Var and {x}.ref is not None: {x} = {x}.ref"


def _arg(w: GoalWriter, n: Value, t: Value, a: Value) -> bool:
    nv, tv = _value(w, n), _value(w, t)
    if nv is None or tv is None:
        return False
    tn, tt, tx = w.temp(), w.temp(), w.temp()
    w.emit(f"{tn} = {nv}; {tt} = {tv}", 1)
    w.emit(_deref(tn), 1)
    w.emit(_deref(tt), 1)
    w.emit(f"if type({tn}) is int and type({tt}) is Term and 0 < {tn} <= len({tt}[1]):", 1)
    w.emit(f"{tx} = {tt}[1][{tn} - 1]", 2)
    w.emit(f"else: arg_check({tn}, {tt}); {w.fail}", 1)
    w.unify_arg(a, tx, 1)
    return True


def _functor(w: GoalWriter, t: Value, f: Value, n: Value) -> bool:
    fv, nv = _value(w, f), _value(w, n)
    if type(t) is Slot and t.i not in w.known:
        if fv is None or nv is None:
            return False  # the built-in raises the instantiation error
        tf, tn = w.temp(), w.temp()  # the usual case built here, the rest (errors) there
        w.emit(f"{tf} = {fv}; {tn} = {nv}", 1)
        w.emit(_deref(tf), 1)
        w.emit(_deref(tn), 1)
        w.emit(f"if type({tf}) is str and type({tn}) is int and {tn} > 0:", 1)
        w.emit(f"v{t.i} = mkt(({tf}, fresh_vars({tn})))", 2)
        w.emit(f"else: v{t.i} = functor_make({tf}, {tn})", 1)
        w.known.add(t.i)
        return True
    tv = _value(w, t)
    if tv is None:
        return False
    tt, tf, tn = w.temp(), w.temp(), w.temp()
    w.emit(f"{tt} = {tv}", 1)
    w.emit(_deref(tt), 1)
    w.emit(f"if type({tt}) is Term: {tf} = {tt}[0]; {tn} = len({tt}[1])", 1)
    w.emit(f"elif type({tt}) is not Var: {tf} = {tt}; {tn} = 0", 1)
    w.emit("else:", 1)
    w.emit(f"{tf} = {fv or 'Var()'}; {tn} = {nv or 'Var()'}", 2)
    w.emit(f"{tt}.ref = functor_make({tf}, {tn}); trail.append({tt})", 2)
    w.unify_arg(f, tf, 1)
    w.unify_arg(n, tn, 1)
    return True

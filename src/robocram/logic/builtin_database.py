"""Database built-ins: assert/asserta/assertz, retract, retractall, clause, dynamic, op."""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from robocram.logic.builtin_spec import Builtin, det, nondet
from robocram.logic.builtin_terms import need_int
from robocram.logic.errors import PrologInstantiationError, PrologPermissionError, PrologTypeError
from robocram.logic.indicator import indicator_key, indicator_pattern
from robocram.logic.loader import parse_indicator
from robocram.logic.terms import Term, Var, deref
from robocram.logic.unify import copy_resolved
from robocram.logic.value import Value

if TYPE_CHECKING:
    from robocram.logic.clause import Clause
    from robocram.logic.engine import Engine
    from robocram.logic.predicate import Pred

__all__: list[str] = []

Args = tuple[Value, ...]


def _assertz(m: Engine, a: Args) -> bool:
    m.kb.assert_term(a[0])
    return True


def _asserta(m: Engine, a: Args) -> bool:
    m.kb.assert_term(a[0], front=True)
    return True


def _split(clause: Value) -> tuple[Value, Value]:
    clause = deref(clause)
    if type(clause) is Term and clause[0] == ":-" and len(clause[1]) == 2:
        return deref(clause[1][0]), clause[1][1]
    return clause, "true"


def _pred_of(m: Engine, head: Value, what: str, modify: bool = False) -> Pred | None:
    """The user predicate of `head`; a built-in is private to clause/2, static to retract."""
    if type(head) is Var:
        raise PrologInstantiationError(f"{what}: the clause head is unbound")
    if type(head) is str:
        key = (head, 0)
    elif type(head) is Term:
        key = (head[0], len(head[1]))
    else:
        raise PrologTypeError("callable", head, f"{what}: {head!r} is not a callable head")
    pred = m.kb._preds.get(key)
    if pred is not None and (pred.system or pred.kind != 0):
        action, kind = ("modify", "static_procedure") if modify else ("access", "private_procedure")
        raise PrologPermissionError(
            action, kind, Term("/", key), f"{what}: {pred.indicator} is a built-in"
        )
    return pred


def _stored(clause: Clause) -> tuple[Value, Value]:
    """The clause as a term to unify with; a ground one needs no fresh copy."""
    return _split(clause.source if clause.nvars == 0 else copy_resolved(clause.source))


def _retract(m: Engine, a: Args) -> Iterator[bool]:
    head, body = _split(a[0])
    pred = _pred_of(m, head, "retract/1", modify=True)
    if pred is None:
        return
    cands, lo = _snapshot(pred, head)
    for i in range(lo, len(cands)):  # the list as the call found it (see _snapshot)
        clause = cands[i]
        if clause.erased:
            continue  # retracted meanwhile (by this or another query)
        h, b = _stored(clause)
        mark = len(m.trail)
        if m.unify(head, h) and m.unify(body, b):
            if not pred.dynamic:
                raise PrologPermissionError(
                    "modify",
                    "static_procedure",
                    Term("/", (pred.name, pred.arity)),
                    f"retract/1: {pred.indicator} is static; declare it dynamic",
                )
            with m.kb._lock:  # released before the answer: a suspended query holds no lock
                won = not clause.erased
                if won:
                    pred.erase(clause)
                    m.kb.mark_changed()
            if won:
                yield True
                continue
        m.undo_to(mark)


def _snapshot(pred: Pred, head: Value) -> tuple[list[Clause], int]:
    """The clauses that can match `head`, as they were at the call, read without a copy:
    a list and where to start in it; the caller reads up to the list's length at the call.

    Clauses are only ever added after the end of a list, or before its start (asserta),
    or the list is replaced: its first `n` entries from `lo` on stay the call's view.
    """
    first = deref(head[1][0]) if type(head) is Term and head[1] else None
    if first is None or type(first) is Var:
        return pred.store, pred.first_live()
    return pred.candidates(first), 0


def _candidates(pred: Pred, head: Value) -> list[Value]:
    """The live clauses that can match `head` by its first argument (a snapshot)."""
    if type(head) is Term and head[1]:
        return pred.live(list(pred.candidates(deref(head[1][0]))))
    return pred.live(list(pred.clauses))


def _retractall(m: Engine, a: Args) -> bool:
    head = deref(a[0])
    pred = _pred_of(m, head, "retractall/1", modify=True)
    if pred is None:
        m.kb.declare_dynamic((head, 0) if type(head) is str else (head[0], len(head[1])))
        return True
    keep = []
    for clause in pred.live(pred.clauses):
        mark = len(m.trail)
        if not m.unify(head, _stored(clause)[0]):
            keep.append(clause)
        m.undo_to(mark)
    with m.kb._lock:
        pred.set_clauses(keep)
        m.kb.mark_changed()
    return True


def _clause(m: Engine, a: Args) -> Iterator[bool]:
    head = deref(a[0])
    pred = _pred_of(m, head, "clause/2")
    if pred is None:
        return
    for clause in _candidates(pred, head):
        h, b = _stored(clause)
        mark = len(m.trail)
        if m.unify(head, h) and m.unify(a[1], b):
            yield True
        m.undo_to(mark)


def _dynamic(m: Engine, a: Args) -> bool:
    spec = deref(a[0])
    while type(spec) is Term and spec[0] in (",", ".") and len(spec[1]) == 2:
        m.kb.declare_dynamic(parse_indicator(spec[1][0]))
        spec = deref(spec[1][1])
    if spec != "[]":
        m.kb.declare_dynamic(parse_indicator(spec))
    return True


def _op(m: Engine, a: Args) -> bool:
    priority = need_int(a[0], "op/3")
    kind = deref(a[1])
    names = deref(a[2])
    todo = [names] if type(names) is str else []
    while type(names) is Term and names[0] == ".":
        todo.append(deref(names[1][0]))
        names = deref(names[1][1])
    for name in todo:
        try:
            m.kb._ops.add(priority, kind, name)
        except ValueError as err:
            raise PrologTypeError("operator_specifier", kind, f"op/3: {err}") from err
        finally:
            m.kb.mark_changed(syntax=True)
    return True


def _current_op(m: Engine, a: Args) -> bool:
    name = deref(a[2])
    spec = m.kb._ops.infix.get(name) or m.kb._ops.prefix.get(name)
    return spec is not None and m.unify(a[0], spec[0]) and m.unify(a[1], spec[1])


def _current_predicate(m: Engine, a: Args) -> Iterator[bool]:
    spec = deref(a[0])
    if type(spec) is Term and spec[0] == ":" and len(spec[1]) == 2:
        spec = deref(spec[1][1])  # Module:Name/Arity: one module here
    if type(spec) is not Var:
        indicator_pattern(spec, "current_predicate/1")
    # Visible user and library predicates with a definition; built-ins are not listed (ISO).
    for pred in list(m.kb._preds.values()):
        if pred.system or pred.name.startswith("$") or pred.kind != 0:
            continue
        if not (pred.clauses or pred.dynamic or pred.pyfn is not None):
            continue
        mark = len(m.trail)
        if m.unify(spec, Term("/", (pred.name, pred.arity))):
            yield True
        m.undo_to(mark)


def _abolish(m: Engine, a: Args) -> bool:
    key = indicator_key(a[0], "abolish/1")
    with m.kb._lock:
        pred = m.kb._preds.get(key)
        if pred is None:
            return True
        if not pred.dynamic:
            raise PrologPermissionError(
                "modify",
                "static_procedure",
                Term("/", key),
                f"abolish/1: {pred.indicator} is static; only dynamic predicates can be abolished",
            )
        del m.kb._preds[key]
        m.kb.mark_changed()
    return True


def _mode(m: Engine, a: Args) -> bool:
    """Accept a DEC-10 mode declaration (`:- mode(p(+, -))`) and ignore it, as SWI does."""
    return True


def _repeat(m: Engine, a: Args) -> Iterator[bool]:
    while True:
        yield True


BUILTINS: tuple[Builtin, ...] = (
    nondet("current_predicate", _current_predicate, 1),
    det("abolish", _abolish, 1),
    nondet("repeat", _repeat, 0),
    det("assert", _assertz, 1),
    det("assertz", _assertz, 1),
    det("asserta", _asserta, 1),
    nondet("retract", _retract, 1),
    det("retractall", _retractall, 1),
    nondet("clause", _clause, 2),
    det("dynamic", _dynamic, 1),
    det("mode", _mode, 1),
    det("op", _op, 3),
    det("current_op", _current_op, 3),
)

"""All-solutions built-ins: findall, bagof and setof (with `^`), aggregate_all."""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from robocram.logic.arith import evaluate
from robocram.logic.builtin_spec import Builtin, det, nondet
from robocram.logic.control import callable_body
from robocram.logic.cycles import WALK_STEPS, check_acyclic
from robocram.logic.errors import PrologDomainError, PrologInstantiationError
from robocram.logic.terms import Term, Var, deref, make_list
from robocram.logic.unify import copy_resolved, order_key, order_key_by, variant_key
from robocram.logic.value import Value

if TYPE_CHECKING:
    from robocram.logic.engine import Engine

__all__ = ["term_variables"]

Args = tuple[Value, ...]


def term_variables(t: Value, seen: dict[Var, None] | None = None) -> list[Var]:
    """Return the unbound variables of a term in depth-first, left-to-right order."""
    found: dict[Var, None] = {} if seen is None else seen
    root = t
    steps = 0
    stack = [t]
    while stack:
        t = deref(stack.pop())
        if type(t) is Var:
            found.setdefault(t, None)
        elif type(t) is Term:
            stack.extend(reversed(t[1]))
            steps += 1
            if steps == WALK_STEPS:  # a big term, perhaps a cyclic one: check once
                check_acyclic(root, "term_variables/2")
    return list(found)


def _term_variables(m: Engine, a: Args) -> bool:
    return m.unify(a[1], make_list(term_variables(a[0])))


def collect(m: Engine, template: Value, goal: Value) -> list[Value]:
    """Copy `template` for every solution of `goal`, leaving no bindings behind."""
    callable_body(goal)  # ISO: the culprit is the whole goal, checked before it runs
    mark = len(m.trail)
    try:
        return [copy_resolved(template) for _ in m.solve(goal, sub=True)]
    finally:
        m.undo_to(mark)


def _findall(m: Engine, a: Args) -> bool:
    return m.unify(a[2], make_list(collect(m, a[0], a[1])))


def _findall4(m: Engine, a: Args) -> bool:
    return m.unify(a[2], make_list(collect(m, a[0], a[1]), a[3]))


def _strip_carets(goal: Value) -> tuple[Value, list[Value]]:
    bound: list[Value] = []
    goal = deref(goal)
    while type(goal) is Term and goal[0] == "^" and len(goal[1]) == 2:
        bound.append(goal[1][0])
        goal = deref(goal[1][1])
    return goal, bound


def _grouped(m: Engine, a: Args, to_set: bool) -> Iterator[bool]:
    goal, bound = _strip_carets(a[1])
    if type(goal) is Var:
        raise PrologInstantiationError("bagof/setof: the goal is unbound")
    excluded: dict[Var, None] = {}
    term_variables(a[0], excluded)
    for b in bound:
        term_variables(b, excluded)
    witness = make_list([v for v in term_variables(goal) if v not in excluded])
    pairs = collect(m, Term("-", (witness, a[0])), goal)
    if not pairs:
        return
    groups: dict[Value, list[tuple[Value, Value]]] = {}
    for pair in pairs:
        w, t = pair[1]
        groups.setdefault(variant_key(w), []).append((w, t))
    entries = list(groups.values())
    # The copies' variables are ordered by age (ISO), that is by first appearance in the
    # solutions, which were copied one after the other.
    ages = {v: i for i, v in enumerate(term_variables(make_list(pairs)))}
    if len(entries) > 1:
        entries.sort(key=lambda e: order_key_by(e[0][0], ages))
    for members in entries:
        mark = len(m.trail)
        # ISO: every witness of the group is unified with the first, so variables that
        # differ only by renaming across solutions become the same variable.
        first = members[0][0]
        if all(m.unify(w, first) for w, _ in members[1:]):
            items = [t for _, t in members]
            if to_set:
                items = _sorted_unique(items, ages)
            if m.unify(witness, first) and m.unify(a[2], make_list(items)):
                yield True
        m.undo_to(mark)


def _sorted_unique(items: list[Value], ages: dict[Var, int] | None = None) -> list[Value]:
    out: list[Value] = []
    keys: list[Value] = []
    keyed = [
        (order_key(item) if ages is None else order_key_by(item, ages), item) for item in items
    ]
    keyed.sort(key=lambda k: k[0])
    for key, item in keyed:
        if not keys or keys[-1] != key:
            out.append(item)
            keys.append(key)
    return out


def _bagof(m: Engine, a: Args) -> Iterator[bool]:
    return _grouped(m, a, False)


def _setof(m: Engine, a: Args) -> Iterator[bool]:
    return _grouped(m, a, True)


def _aggregate_all(m: Engine, a: Args) -> bool:
    spec = deref(a[0])
    if spec == "count":
        mark = len(m.trail)
        count = sum(1 for _ in m.solve(a[1], sub=True))
        m.undo_to(mark)
        return m.unify(a[2], count)
    if type(spec) is not Term or len(spec[1]) not in (1, 2):
        raise PrologDomainError(
            "aggregate_spec",
            spec,
            f"aggregate_all/3: {spec!r} is not count, sum/1, max/1, min/1, bag/1 or set/1",
        )
    kind, inner = spec[0], spec[1]
    if kind in ("max", "min") and len(inner) == 2:
        found = collect(m, Term("-", inner), a[1])
        if not found:
            return False
        scored = [(evaluate(p[1][0]), p[1][1]) for p in found]
        best = max(scored, key=lambda s: s[0]) if kind == "max" else min(scored, key=lambda s: s[0])
        return m.unify(a[2], Term(kind, best))
    values = collect(m, inner[0], a[1])
    if kind == "count":
        return m.unify(a[2], len(values))
    if kind == "bag":
        return m.unify(a[2], make_list(values))
    if kind == "set":
        return m.unify(a[2], make_list(_sorted_unique(values)))
    if kind == "sum":
        return m.unify(a[2], sum((evaluate(v) for v in values), 0))
    if kind in ("max", "min"):
        if not values:
            return False
        numbers = [evaluate(v) for v in values]
        return m.unify(a[2], max(numbers) if kind == "max" else min(numbers))
    raise PrologDomainError("aggregate_spec", spec, f"aggregate_all/3: unknown aggregate {kind!r}")


BUILTINS: tuple[Builtin, ...] = (
    det("term_variables", _term_variables, 2),
    det("findall", _findall, 3),
    det("findall", _findall4, 4),
    nondet("bagof", _bagof, 3),
    nondet("setof", _setof, 3),
    det("aggregate_all", _aggregate_all, 3),
)

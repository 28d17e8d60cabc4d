"""List built-ins written in Python for speed: length, sorting, sums and extremes."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING

from robocram.logic.arith import Number, evaluate
from robocram.logic.builtin_spec import Builtin, det, nondet
from robocram.logic.builtin_terms import list_items, need_int
from robocram.logic.cycles import list_prefix
from robocram.logic.errors import PrologDomainError, PrologInstantiationError, PrologTypeError
from robocram.logic.functor_arg import fresh_vars
from robocram.logic.long_work import checked_keys, checked_list, checked_sort, fresh_variables
from robocram.logic.terms import NIL, Term, Var, deref, make_list
from robocram.logic.unify import order_key
from robocram.logic.value import Value

if TYPE_CHECKING:
    from robocram.logic.engine import Engine

__all__: list[str] = []

Args = tuple[Value, ...]


def _length(m: Engine, a: Args) -> Iterator[bool]:
    cells, t = list_prefix(a[0], "length/2", m.budget.check)
    n = len(cells)
    if type(t) is not Var:
        if t != NIL or type(t) is not str:
            raise PrologTypeError("list", t, f"length/2: expected a list, got {t!r}")
        if m.unify(a[1], n):
            yield True
        return
    want = deref(a[1])
    if type(want) is not Var:
        k = need_int(want, "length/2")
        if k < 0:
            raise PrologDomainError("not_less_than_zero", k, f"length/2: length {k} is negative")
        if k >= n and m.unify(t, checked_list(fresh_variables(k - n, m.budget), m.budget)):
            yield True
        return
    extra = 0
    while True:
        mark = len(m.trail)
        if m.unify(t, make_list(fresh_vars(extra))) and m.unify(want, n + extra):
            yield True
        m.undo_to(mark)
        extra += 1


def _sorted(
    m: Engine, items: list[Value], reverse: bool = False
) -> list[tuple[tuple[object, ...], Value]]:
    """(standard-order key, item) pairs sorted by key, checking the limits as it goes."""
    keys = checked_keys(items, order_key, m.budget)
    return checked_sort(list(zip(keys, items, strict=True)), m.budget, reverse)


def _msort(m: Engine, a: Args) -> bool:
    pairs = _sorted(m, list_items(a[0], "msort/2", m.budget.check))
    return m.unify(a[1], checked_list([item for _, item in pairs], m.budget))


def _sort(m: Engine, a: Args) -> bool:
    pairs = _sorted(m, list_items(a[0], "sort/2", m.budget.check))
    return m.unify(a[1], checked_list(_dedup(pairs), m.budget))


def _dedup(pairs: list[tuple[tuple[object, ...], Value]]) -> list[Value]:
    out: list[Value] = []
    last: object = None
    for key, item in pairs:
        if not out or key != last:
            out.append(item)
            last = key
    return out


def _sort4(m: Engine, a: Args) -> bool:
    key_index = need_int(a[0], "sort/4")
    order = deref(a[1])
    if order not in ("@<", "@>", "@=<", "@>="):
        raise PrologDomainError(
            "order", order, f"sort/4: order {order!r} is not @<, @>, @=< or @>="
        )
    items = list_items(a[2], "sort/4", m.budget.check)

    def key(item: Value) -> tuple[object, ...]:
        if key_index == 0:
            return order_key(item)
        t = deref(item)
        if type(t) is not Term or len(t[1]) < key_index:
            raise PrologTypeError("compound", t, f"sort/4: {t!r} has no argument {key_index}")
        return order_key(t[1][key_index - 1])

    keys = checked_keys(items, key, m.budget)
    pairs = checked_sort(list(zip(keys, items, strict=True)), m.budget, order in ("@>", "@>="))
    ordered = _dedup(pairs) if order in ("@<", "@>") else [item for _, item in pairs]
    return m.unify(a[3], checked_list(ordered, m.budget))


def _keysort(m: Engine, a: Args) -> bool:
    items = list_items(a[0], "keysort/2", m.budget.check)
    for item in items:
        t = deref(item)
        if type(t) is Var:
            raise PrologInstantiationError("keysort/2: an element is unbound; expected Key-Value")
        if type(t) is not Term or t[0] != "-" or len(t[1]) != 2:
            raise PrologTypeError("pair", t, f"keysort/2: {t!r} is not a Key-Value pair")
    keys = checked_keys(items, lambda p: order_key(deref(p)[1][0]), m.budget)
    pairs = checked_sort(list(zip(keys, items, strict=True)), m.budget)
    return m.unify(a[1], checked_list([item for _, item in pairs], m.budget))


def _sum_list(m: Engine, a: Args) -> bool:
    return m.unify(a[1], sum((evaluate(x) for x in list_items(a[0], "sum_list/2")), 0))


def _extreme(name: str, pick: Callable[[list[Number]], Number]) -> Builtin:
    def run(m: Engine, a: Args) -> bool:
        values = [evaluate(x) for x in list_items(a[0], f"{name}/2")]
        return bool(values) and m.unify(a[1], pick(values))

    return det(name, run, 2)


def _numlist(m: Engine, a: Args) -> bool:
    low, high = need_int(a[0], "numlist/3"), need_int(a[1], "numlist/3")
    return low <= high and m.unify(a[2], checked_list(range(low, high + 1), m.budget))


def _max_member(m: Engine, a: Args) -> bool:
    items = list_items(a[1], "max_member/2")
    return bool(items) and m.unify(a[0], max(items, key=order_key))


def _min_member(m: Engine, a: Args) -> bool:
    items = list_items(a[1], "min_member/2")
    return bool(items) and m.unify(a[0], min(items, key=order_key))


BUILTINS: tuple[Builtin, ...] = (
    _extreme("max_list", max),
    _extreme("min_list", min),
    nondet("length", _length, 2),
    det("msort", _msort, 2),
    det("sort", _sort, 2),
    det("sort", _sort4, 4),
    det("keysort", _keysort, 2),
    det("sum_list", _sum_list, 2),
    det("numlist", _numlist, 3),
    det("max_member", _max_member, 2),
    det("min_member", _min_member, 2),
)

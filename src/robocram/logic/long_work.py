"""Built-ins whose one call may run for seconds check the query's limits as they go.

A goal like `numlist(1, 3000000, L)` is one inference, so the machine's inference count
never sees it; these helpers do the long part in chunks of CHUNK items and call
`Budget.check()` between chunks, so that a time limit or a stop request ends it soon.
Large results are built with the cyclic collector paused (see bulk.py): they are all
live, and collections during the build would traverse them again and again.
"""

from __future__ import annotations

import heapq
from collections.abc import Callable, Iterable, Sequence
from itertools import islice

from robocram.logic.bulk import paused_gc
from robocram.logic.functor_arg import fresh_vars
from robocram.logic.limits import Budget
from robocram.logic.terms import NIL, Var, make_term
from robocram.logic.value import Value

__all__ = ["CHUNK", "checked_keys", "checked_list", "checked_sort", "fresh_variables"]

CHUNK = 1 << 15  # items between two limit checks
Key = tuple[object, ...]  # a standard-order key (unify.order_key)
Pair = tuple[Key, Value]


def checked_list(items: Sequence[Value], budget: Budget, tail: Value = NIL) -> Value:
    """`make_list(items, tail)`, checking the limits every CHUNK cells.

    >>> from robocram.logic.limits import Budget
    >>> checked_list([1, 2], Budget(None, None))
    [1,2]
    """
    result = tail
    if len(items) <= CHUNK:
        for item in reversed(items):
            result = make_term((".", (item, result)))
        return result
    with paused_gc():
        for end in range(len(items), 0, -CHUNK):
            budget.check()
            for i in range(end - 1, max(end - CHUNK, 0) - 1, -1):
                result = make_term((".", (items[i], result)))
    return result


def fresh_variables(n: int, budget: Budget) -> list[Var]:
    """`n` new variables, checking the limits every CHUNK of them."""
    if n <= CHUNK:
        return list(fresh_vars(n))
    out: list[Var] = []
    with paused_gc():
        for start in range(0, n, CHUNK):
            budget.check()
            out.extend(fresh_vars(min(CHUNK, n - start)))
    return out


def checked_keys(items: Sequence[Value], key: Callable[[Value], Key], budget: Budget) -> list[Key]:
    """`[key(x) for x in items]`, checking the limits every CHUNK items."""
    if len(items) <= CHUNK:
        return [key(x) for x in items]
    out: list[Key] = []
    for start in range(0, len(items), CHUNK):
        budget.check()
        out.extend([key(x) for x in items[start : start + CHUNK]])
    return out


def checked_sort(pairs: list[Pair], budget: Budget, reverse: bool = False) -> list[Pair]:
    """Sort (key, item) pairs by key, stably, in sorted runs merged with limit checks."""
    if len(pairs) <= 2 * CHUNK:
        return sorted(pairs, key=_first, reverse=reverse)
    runs: list[Iterable[Pair]] = []
    for start in range(0, len(pairs), CHUNK):
        budget.check()
        runs.append(sorted(pairs[start : start + CHUNK], key=_first, reverse=reverse))
    out: list[Pair] = []
    merged = heapq.merge(*runs, key=_first, reverse=reverse)
    with paused_gc():
        while True:
            budget.check()
            n = len(out)
            out.extend(islice(merged, CHUNK))
            if len(out) - n < CHUNK:
                return out


def _first(pair: Pair) -> Key:
    return pair[0]

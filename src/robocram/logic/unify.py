"""Unification with a trail, standard order of terms, and copying terms out of bindings."""

from __future__ import annotations

from collections.abc import Callable

from robocram.logic.cycles import check_acyclic, cyclic_error, is_acyclic
from robocram.logic.terms import PString, Term, Var, make_term, make_var
from robocram.logic.value import Value

__all__ = [
    "copy_resolved",
    "identical",
    "is_acyclic",
    "order_key",
    "order_key_by",
    "undo",
    "unify",
    "unify_iterative",
    "unify_rational",
    "variant_key",
]

_PRIMITIVE = frozenset([str, int, float, PString])
BindCheck = Callable[[Var, Value], bool]
_FAST_STEPS = 100_000


def unify(a: Value, b: Value, trail: list[Var]) -> bool:
    """Unify two terms, recording each bound variable on `trail`.

    >>> x = Var(); unify(Term("f", (x,)), Term("f", (1,)), []), x.ref
    (True, 1)

    Cyclic (rational) terms such as `X = f(X)` take the slower `unify_rational` once a
    pair of terms needs more than `_FAST_STEPS` compound steps or Python's stack runs out.
    """
    steps = 0
    while True:
        while type(a) is Var:
            r = a.ref
            if r is None:
                break
            a = r
        while type(b) is Var:
            r = b.ref
            if r is None:
                break
            b = r
        if a is b:
            return True
        ta = type(a)
        tb = type(b)
        if ta is Var:
            a.ref = b
            trail.append(a)
            return True
        if tb is Var:
            b.ref = a
            trail.append(b)
            return True
        if ta is Term:
            if tb is not Term or a[0] != b[0]:
                return False
            aa = a[1]
            ab = b[1]
            n = len(aa) - 1
            if n != len(ab) - 1:
                return False
            steps += 1
            if steps > _FAST_STEPS:
                return unify_rational(a, b, trail)
            try:
                if n == 1:  # a list cell: its head, without a loop (the tail is next)
                    x = aa[0]
                    y = ab[0]
                    while type(x) is Var and x.ref is not None:
                        x = x.ref
                    while type(y) is Var and y.ref is not None:
                        y = y.ref
                    if x is not y:
                        if type(x) is Var:
                            x.ref = y
                            trail.append(x)
                        elif type(y) is Var:
                            y.ref = x
                            trail.append(y)
                        elif type(x) is type(y) and type(x) is not Term:
                            if x != y:
                                return False
                        elif not unify(x, y, trail):
                            return False
                else:
                    for i in range(n):  # variables and constants here, compounds recursively
                        x = aa[i]
                        y = ab[i]
                        while type(x) is Var and x.ref is not None:
                            x = x.ref
                        while type(y) is Var and y.ref is not None:
                            y = y.ref
                        if x is y:
                            continue
                        if type(x) is Var:
                            x.ref = y
                            trail.append(x)
                        elif type(y) is Var:
                            y.ref = x
                            trail.append(y)
                        elif type(x) is type(y) and type(x) is not Term:
                            if x != y:
                                return False
                        elif not unify(x, y, trail):
                            return False
            except RecursionError:
                return unify_rational(a, b, trail)
            a = aa[n]
            b = ab[n]
            continue
        if ta is tb:
            return bool(a == b)
        if ta in _PRIMITIVE or tb in _PRIMITIVE or tb is Term:
            return False
        return bool(a == b)


def unify_rational(a: Value, b: Value, trail: list[Var]) -> bool:
    """Unify without recursion, terminating on cyclic terms (pairs already met are equal).

    >>> x, y = Var(), Var(); t = []
    >>> unify(x, Term("f", (x,)), t) and unify(y, Term("f", (y,)), t) and unify(x, y, t)
    True
    """
    return unify_iterative(a, b, trail, None)


def unify_iterative(a: Value, b: Value, trail: list[Var], may_bind: BindCheck | None) -> bool:
    """Unify with an explicit stack; compound pairs met before count as equal (so cyclic
    terms end), and `may_bind(var, value)` vets each binding of a variable to a compound
    (the occurs check).
    """
    seen: set[tuple[int, int]] = set()
    stack = [(a, b)]
    while stack:
        a, b = stack.pop()
        while type(a) is Var and a.ref is not None:
            a = a.ref
        while type(b) is Var and b.ref is not None:
            b = b.ref
        if a is b:
            continue
        if type(a) is not Var and type(b) is Var:
            a, b = b, a
        if type(a) is Var:
            if may_bind is not None and type(b) is Term and not may_bind(a, b):
                return False
            a.ref = b
            trail.append(a)
        elif type(a) is Term and type(b) is Term:
            if a[0] != b[0] or len(a[1]) != len(b[1]):
                return False
            pair = (id(a), id(b))
            if pair not in seen:
                seen.add(pair)
                stack.extend(zip(a[1], b[1], strict=True))
        elif not unify(a, b, trail):
            return False
    return True


def undo(trail: list[Var], mark: int) -> None:
    """Unbind every variable bound since the trail had length `mark`."""
    n = len(trail) - mark  # taken once: a long trail's length is a new int each time
    if n > 8:  # a long undo: one pass over a slice beats popping
        for v in trail[mark:]:
            v.ref = None
        del trail[mark:]
        return
    while n > 0:
        trail.pop().ref = None
        n -= 1


def copy_resolved(term: Value, mapping: dict[Var, Var] | None = None) -> Value:
    """Copy a term with bindings applied and fresh variables for unbound ones.

    Terms nested deeper than Python's stack allows are copied by `_copy_deep` instead.
    """
    if mapping is None:
        mapping = {}
    try:
        return _copy(term, mapping)
    except RecursionError:
        return _copy_deep(term, mapping)


def _copy(term: Value, mapping: dict[Var, Var]) -> Value:
    while type(term) is Var:
        if term.ref is None:
            fresh = mapping.get(term)
            if fresh is None:
                fresh = mapping[term] = make_var()
                fresh.ref = None
            return fresh
        term = term.ref
    if type(term) is not Term:
        return term
    if term[0] == "." and len(term[1]) == 2:
        items = []
        saved: Value = term
        power = 64
        while type(term) is Term and term[0] == "." and len(term[1]) == 2:
            items.append(_copy(term[1][0], mapping))
            term = term[1][1]
            while type(term) is Var and term.ref is not None:
                term = term.ref
            if term is saved:  # Brent's test: the tail came back to a cell seen before
                raise cyclic_error("copying a list")
            if len(items) == power:
                saved = term
                power <<= 1
        tail = _copy(term, mapping)
        for item in reversed(items):
            tail = make_term((".", (item, tail)))
        return tail
    return make_term((term[0], tuple([_copy(a, mapping) for a in term[1]])))


def _copy_deep(term: Value, mapping: dict[Var, Var]) -> Value:
    """`copy_resolved` with an explicit stack: any depth; a cyclic term is an error."""
    check_acyclic(term, "copying a term")
    out: list[Value] = []
    stack: list[tuple[bool, Value]] = [(False, term)]
    while stack:
        built, t = stack.pop()
        if built:  # all arguments of compound t are on `out`: assemble it
            n = len(t[1])
            args = tuple(out[len(out) - n :])
            del out[len(out) - n :]
            out.append(make_term((t[0], args)))
            continue
        while type(t) is Var and t.ref is not None:
            t = t.ref
        if type(t) is Var:
            fresh = mapping.get(t)
            if fresh is None:
                fresh = mapping[t] = make_var()
                fresh.ref = None
            out.append(fresh)
        elif type(t) is Term:
            stack.append((True, t))
            stack.extend((False, a) for a in reversed(t[1]))
        else:
            out.append(t)
    return out[0]


def identical(a: Value, b: Value) -> bool:
    """`a == b` in Prolog: the same term, variables included, without building order keys.

    >>> x = Var(); identical(Term("f", (x, 1)), Term("f", (x, 1))), identical(1, 1.0)
    (True, False)
    """
    stack = [(a, b)]
    seen: set[tuple[int, int]] | None = None
    steps = 0
    while stack:
        a, b = stack.pop()
        while type(a) is Var and a.ref is not None:
            a = a.ref
        while type(b) is Var and b.ref is not None:
            b = b.ref
        if a is b:
            continue
        ta = type(a)
        if ta is not type(b) or ta is Var:
            return False
        if ta is Term:
            if a[0] != b[0] or len(a[1]) != len(b[1]):
                return False
            steps += 1
            if steps > _FAST_STEPS:  # perhaps cyclic: compare each pair of compounds once
                seen = set() if seen is None else seen
                if (id(a), id(b)) in seen:
                    continue
                seen.add((id(a), id(b)))
            stack.extend(zip(a[1], b[1], strict=True))
        elif ta in _PRIMITIVE:
            if a != b:
                return False
        else:
            return False  # opaque objects: identical only when the same object
    return True


def order_key(term: Value) -> tuple[object, ...]:
    """Key giving the standard order: Var < Number < Atom < String < Compound < other.

    >>> sorted([Term("f", (1,)), "b", 2, 1.0, "a"], key=order_key)
    [1.0, 2, 'a', 'b', f(1)]
    """
    while type(term) is Var:
        if term.ref is None:
            return (0, id(term))
        term = term.ref
    t = type(term)
    if t is int or t is float:
        return (1, term, 0 if t is float else 1)
    if t is str:
        return (3, term)
    if t is PString:
        return (4, term.text)
    if t is Term:
        return (5, len(term[1]), term[0], tuple([order_key(a) for a in term[1]]))
    return (6, type(term).__name__, id(term))


def order_key_by(term: Value, ages: dict[Var, int]) -> tuple[object, ...]:
    """`order_key` with variables ranked by `ages` (those not in it after, by address)."""
    while type(term) is Var:
        if term.ref is None:
            age = ages.get(term)
            return (0, 0, age) if age is not None else (0, 1, id(term))
        term = term.ref
    if type(term) is Term:
        return (5, len(term[1]), term[0], tuple([order_key_by(a, ages) for a in term[1]]))
    return order_key(term)


def variant_key(term: Value) -> tuple[object, ...]:
    """Key equal for terms that are variants (equal up to renaming variables)."""
    names: dict[int, int] = {}

    def walk(t: Value) -> object:
        while type(t) is Var:
            if t.ref is None:
                return ("$VAR", names.setdefault(id(t), len(names)))
            t = t.ref
        if type(t) is Term:
            return (t[0], tuple([walk(a) for a in t[1]]))
        return (type(t).__name__, t if type(t) in _PRIMITIVE else id(t))

    return (walk(term),)

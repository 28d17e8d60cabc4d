"""Built-ins on terms: unification, comparison, type tests, construction, throw, counting."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING

from robocram.logic.builtin_spec import Builtin, det, nondet
from robocram.logic.convert import NONE
from robocram.logic.cycles import list_prefix
from robocram.logic.errors import (
    PrologDomainError,
    PrologInstantiationError,
    PrologResourceError,
    PrologTypeError,
    error_from_ball,
)
from robocram.logic.functor_arg import arg_check, functor_make, need_int
from robocram.logic.terms import NIL, PString, Term, Var, deref
from robocram.logic.unify import copy_resolved, identical, is_acyclic, order_key
from robocram.logic.univ import univ_compose, univ_list
from robocram.logic.value import Value

if TYPE_CHECKING:
    from robocram.logic.engine import Engine

__all__ = ["list_items", "need_int"]

Args = tuple[Value, ...]


def list_items(t: Value, what: str, check: Callable[[], None] | None = None) -> list[Value]:
    """Return the elements of a proper list; raise for partial or non-lists.

    `check` (the query's limit check) is called as a long list is read.
    """
    items, t = list_prefix(t, what, check)
    if type(t) is Var:
        raise PrologInstantiationError(f"{what}: the list is partial (ends in a variable)")
    if t != NIL or type(t) is not str:
        raise PrologTypeError("list", t, f"{what}: expected a list, got {t!r}")
    return items


def _unify(m: Engine, a: Args) -> bool:
    return m.unify(a[0], a[1])


def _not_unify(m: Engine, a: Args) -> bool:
    mark = len(m.trail)
    ok = m.unify(a[0], a[1])
    m.undo_to(mark)
    return not ok


def _compare_terms(a: Value, b: Value) -> int:
    ka, kb = order_key(a), order_key(b)
    return (ka > kb) - (ka < kb)


def _ordering(test: Value) -> Value:
    def run(m: Engine, a: Args) -> bool:
        return bool(test(_compare_terms(a[0], a[1])))

    return run


def _compare(m: Engine, a: Args) -> bool:
    c = _compare_terms(a[1], a[2])
    return m.unify(a[0], "<" if c < 0 else ">" if c > 0 else "=")


def _type_test(name: str, test: Value) -> Builtin:
    return det(name, lambda m, a: bool(test(deref(a[0]))), 1)


_OPAQUE_EXCLUDED = (str, int, float, Term, Var, PString)


def _is_list(t: Value) -> bool:
    try:
        t = list_prefix(t, "is_list/1")[1]
    except PrologResourceError:
        return False  # a cyclic list is not a list
    return type(t) is str and t == NIL


def _is_ground(t: Value) -> bool:
    stack = [t]
    seen: set[int] = set()  # a cyclic term revisits its compounds
    while stack:
        t = deref(stack.pop())
        if type(t) is Var:
            return False
        if type(t) is Term and id(t) not in seen:
            seen.add(id(t))
            stack.extend(t[1])
    return True


def _functor(m: Engine, a: Args) -> bool:
    t = deref(a[0])
    if type(t) is Term:
        return m.unify(a[1], t[0]) and m.unify(a[2], len(t[1]))
    if type(t) is not Var:
        return m.unify(a[1], t) and m.unify(a[2], 0)
    return m.unify(t, functor_make(a[1], a[2]))


def _arg(m: Engine, a: Args) -> bool:
    n = arg_check(a[0], a[1])
    t = deref(a[1])
    return 1 <= n <= len(t[1]) and m.unify(a[2], t[1][n - 1])


def _univ(m: Engine, a: Args) -> bool:
    t = deref(a[0])
    items = univ_list(t)
    if items is not None:
        return m.unify(a[1], items)
    return m.unify(t, univ_compose(a[1]))


def _copy_term(m: Engine, a: Args) -> bool:
    return m.unify(a[1], copy_resolved(a[0]))


def _throw(m: Engine, a: Args) -> bool:
    ball = copy_resolved(a[0])
    if type(ball) is Var:
        raise PrologInstantiationError("throw/1: the ball is unbound")
    raise error_from_ball(ball)


def _between(m: Engine, a: Args) -> Iterator[bool]:
    low = need_int(a[0], "between/3")
    high_t = deref(a[1])
    high = high_t if high_t in ("inf", "infinite") else need_int(high_t, "between/3")
    x = deref(a[2])
    if type(x) is not Var:
        if need_int(x, "between/3") >= low and (high in ("inf", "infinite") or x <= high):
            yield True
        return
    i = low
    while high in ("inf", "infinite") or i <= high:
        mark = len(m.trail)
        if m.unify(x, i):
            yield True
        m.undo_to(mark)
        i += 1


def _succ(m: Engine, a: Args) -> bool:
    x = deref(a[0])
    if type(x) is not Var:
        n = need_int(x, "succ/2")
        if n < 0:
            raise PrologTypeError("not_less_than_zero", n, f"succ/2: {n} is negative")
        return m.unify(a[1], n + 1)
    y = need_int(a[1], "succ/2")
    if y < 0:
        raise PrologTypeError("not_less_than_zero", y, f"succ/2: {y} is negative")
    return y > 0 and m.unify(x, y - 1)


def _plus(m: Engine, a: Args) -> bool:
    x, y, z = deref(a[0]), deref(a[1]), deref(a[2])
    if type(z) is Var:
        return m.unify(z, need_int(x, "plus/3") + need_int(y, "plus/3"))
    if type(y) is Var:
        return m.unify(y, need_int(z, "plus/3") - need_int(x, "plus/3"))
    return m.unify(x, need_int(z, "plus/3") - need_int(y, "plus/3"))


def _halt(m: Engine, a: Args) -> bool:
    raise PrologDomainError("embedded", "halt", "halt/0: not allowed in an embedded knowledge base")


def _unify_with_occurs_check(m: Engine, a: Args) -> bool:
    mark = len(m.trail)
    if m.unify(a[0], a[1]) and is_acyclic(a[0]):
        return True
    m.undo_to(mark)  # the only way plain unification differs: it built a cyclic term
    return False


def _subsumes_term(m: Engine, a: Args) -> bool:
    """General subsumes Specific: they unify without binding any variable of Specific."""
    specific_vars = _variables(a[1])
    mark = len(m.trail)
    try:
        if not m.unify(a[0], a[1]):
            return False
        after = [deref(v) for v in specific_vars]
        return all(type(v) is Var for v in after) and len({id(v) for v in after}) == len(after)
    finally:
        m.undo_to(mark)


def _variables(t: Value) -> list[Var]:
    found: dict[int, Var] = {}
    stack = [t]
    seen: set[int] = set()
    while stack:
        t = deref(stack.pop())
        if type(t) is Var:
            found.setdefault(id(t), t)
        elif type(t) is Term and id(t) not in seen:
            seen.add(id(t))
            stack.extend(t[1])
    return list(found.values())


BUILTINS: tuple[Builtin, ...] = (
    det("unify_with_occurs_check", _unify_with_occurs_check, 2),
    det("subsumes_term", _subsumes_term, 2),
    det("==", lambda m, a: identical(a[0], a[1]), 2),
    det("\\==", lambda m, a: not identical(a[0], a[1]), 2),
    det("@<", _ordering(lambda c: c < 0), 2),
    det("@>", _ordering(lambda c: c > 0), 2),
    det("@=<", _ordering(lambda c: c <= 0), 2),
    det("@>=", _ordering(lambda c: c >= 0), 2),
    _type_test("var", lambda t: type(t) is Var),
    _type_test("nonvar", lambda t: type(t) is not Var),
    _type_test("bound", lambda t: type(t) is not Var),
    _type_test("atom", lambda t: type(t) is str),
    _type_test("number", lambda t: type(t) in (int, float)),
    _type_test("integer", lambda t: type(t) is int),
    _type_test("float", lambda t: type(t) is float),
    _type_test("atomic", lambda t: type(t) is not Var and type(t) is not Term),
    _type_test("compound", lambda t: type(t) is Term),
    _type_test("callable", lambda t: type(t) in (str, Term)),
    _type_test("string", lambda t: type(t) is PString),
    _type_test("is_list", lambda t: _is_list(t)),
    _type_test("ground", lambda t: _is_ground(t)),
    _type_test("acyclic_term", is_acyclic),
    _type_test("python_object", lambda t: type(t) not in _OPAQUE_EXCLUDED or t is NONE),
    det("=", _unify, 2),
    det("\\=", _not_unify, 2),
    det("compare", _compare, 3),
    det("functor", _functor, 3),
    det("arg", _arg, 3),
    det("=..", _univ, 2),
    det("copy_term", _copy_term, 2),
    det("throw", _throw, 1),
    nondet("between", _between, 3),
    det("succ", _succ, 2),
    det("plus", _plus, 3),
    det("halt", _halt, 0, 1),
)

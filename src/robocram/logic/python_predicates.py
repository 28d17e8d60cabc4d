"""Python code called from Prolog: registered generator predicates, py_fun and py_pred."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING

from robocram.logic.builtin_spec import Builtin, det
from robocram.logic.convert import to_prolog, to_python
from robocram.logic.errors import (
    PrologError,
    PrologExistenceError,
    PrologHostError,
    PrologInstantiationError,
)
from robocram.logic.terms import Var, deref
from robocram.logic.value import Value

if TYPE_CHECKING:
    from robocram.logic.engine import Engine
    from robocram.logic.predicate import Pred

__all__ = ["python_solutions"]


def python_solutions(m: Engine, p: Pred, args: tuple[Value, ...]) -> Iterator[bool]:
    """Run a Python predicate; unify each yielded tuple with the call's arguments.

    A Python exception becomes a `PrologHostError` naming the predicate (one generator
    per call, not two: a transport makes some 400 such calls).
    """
    fn = p.pyfn
    assert fn is not None
    py_args = [to_python(a) for a in args]
    trail = m.trail
    try:
        result = fn(*py_args)
    except PrologError:
        raise
    except Exception as err:
        raise PrologHostError(err, p.indicator) from err
    solutions = iter(result)
    while True:
        try:
            solution = next(solutions)
        except StopIteration:
            return
        except PrologError:
            raise
        except Exception as err:
            raise PrologHostError(err, p.indicator) from err
        if solution is None:
            yield True
            continue
        if not isinstance(solution, tuple | list) or len(solution) != p.arity:
            raise PrologError(
                f"Python predicate {p.indicator} yielded {solution!r}; yield a tuple of"
                f" {p.arity} values (one per argument) or None"
            )
        mark = len(trail)
        if all(m.unify(a, to_prolog(v)) for a, v in zip(args, solution, strict=True)):
            yield True
        else:
            m.undo_to(mark)


def _host_call(fn: Callable[..., object], args: list[Value], where: str) -> Value:
    try:
        return fn(*args)
    except PrologError:
        raise
    except Exception as err:
        raise PrologHostError(err, where) from err


def _resolve_callable(m: Engine, f: Value, what: str) -> Callable[..., object]:
    f = deref(f)
    if type(f) is Var:
        raise PrologInstantiationError(
            f"{what}: the function is unbound; pass a callable or a name"
        )
    if callable(f) and not isinstance(f, str):
        return f
    fn = m.kb._functions.get(f) if isinstance(f, str) else None
    if fn is None:
        known = ", ".join(sorted(m.kb._functions)) or "none registered"
        raise PrologExistenceError(
            "python_function",
            f,
            f"{what}: no Python function named {f!r}; register it with"
            f" kb.register_function({f!r}, fn) (known: {known})",
        )
    return fn


def _py_fun(m: Engine, args: tuple[Value, ...]) -> bool:
    fn = _resolve_callable(m, args[0], "py_fun")
    result = _host_call(fn, [to_python(a) for a in args[1:-1]], f"py_fun({args[0]!r})")
    return m.unify(args[-1], to_prolog(result))


def _py_pred(m: Engine, args: tuple[Value, ...]) -> bool:
    fn = _resolve_callable(m, args[0], "py_pred")
    return bool(_host_call(fn, [to_python(a) for a in args[1:]], f"py_pred({args[0]!r})"))


BUILTINS: tuple[Builtin, ...] = (
    det("py_fun", _py_fun, *range(2, 10)),
    det("py_pred", _py_pred, *range(1, 9)),
)

"""One built-in predicate as a value: name, arities, kind and code.

Each `builtin_*` module lists its built-ins in a `BUILTINS` tuple of these; `system` builds
the shared, frozen table from those tuples. Nothing is registered as a side effect of
importing a module.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.logic.engine import DetFn, NondetFn
from robocram.logic.predicate import DET, NONDET

__all__ = ["Builtin", "det", "nondet"]


@dataclass(frozen=True)
class Builtin:
    """A built-in predicate for every arity in `arities`, run by `fn`."""

    name: str
    arities: tuple[int, ...]
    kind: int
    fn: DetFn | NondetFn


def det(name: str, fn: DetFn, *arities: int) -> Builtin:
    """A deterministic built-in: `fn(engine, args) -> bool` (True = success)."""
    return Builtin(name, arities, DET, fn)


def nondet(name: str, fn: NondetFn, *arities: int) -> Builtin:
    """A nondeterministic built-in: a generator yielding True per solution.

    Yielding False instead marks the last solution, so that no choicepoint is left.
    """
    return Builtin(name, arities, NONDET, fn)

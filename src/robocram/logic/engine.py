"""What built-ins and control constructs need from the solver and its knowledge base.

Built-ins are called with the running machine, and the machine runs against a knowledge
base; both are described here as `Protocol`s so that the built-in modules, the control
constructs and the machine import this file instead of each other (no import cycles).
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator
from typing import Protocol

from robocram.logic.choicepoints import ChoicePoint
from robocram.logic.limits import Budget
from robocram.logic.operators import OperatorTable
from robocram.logic.predicate import Key, Pred
from robocram.logic.terms import Var
from robocram.logic.value import Value

__all__ = ["Database", "DetFn", "Engine", "NondetFn"]


class Database(Protocol):
    """The knowledge base as the machine and the database built-ins see it."""

    _preds: dict[Key, Pred]
    _ops: OperatorTable
    _functions: dict[str, Callable[..., object]]
    _lock: threading.RLock
    _flags: dict[str, Value]
    _generation: int

    def assert_clause(self, clause: Value, front: bool = False) -> None: ...

    def assert_term(self, clause: Value, front: bool = False) -> None: ...

    def declare_dynamic(self, key: Key) -> None: ...

    def mark_changed(self, syntax: bool = False) -> None: ...

    def similar_predicates(self, name: str, arity: int) -> list[str]: ...


class Engine(Protocol):
    """The running solver: its trail, unification, and nested solving."""

    kb: Database
    trail: list[Var]
    occurs_check: str  # the flag's value: false, true or error
    budget: Budget  # the query's limits, which long built-ins check as they go

    def unify(self, a: Value, b: Value) -> bool: ...

    def undo_to(self, mark: int) -> None: ...

    def solve(
        self, goal: Value, sub: bool = False, cps: list[ChoicePoint] | None = None
    ) -> Iterator[None]: ...


DetFn = Callable[[Engine, tuple[Value, ...]], bool]
NondetFn = Callable[[Engine, tuple[Value, ...]], Iterator[bool]]

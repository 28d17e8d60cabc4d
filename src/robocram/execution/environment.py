"""Environments: what a ``with`` block switches on so the same PERFORM runs somewhere else.

An environment is a name, a knowledge base with its facts (groundings, matching facts),
a set of process modules, a location resolver and context variables. Entering it binds
the knowledge base and resolver as current, sets the variables and starts the modules
(CRAM's ``on-real-pr2`` / ``with-simulated-robot`` idea); leaving undoes all of it.
"""

from __future__ import annotations

import contextvars
import threading
from collections.abc import Iterable, Iterator, Mapping
from contextlib import ExitStack, contextmanager
from types import TracebackType
from typing import Any

from robocram.designators import (
    LocationResolver,
    install_designator_predicates,
    using_location_resolver,
)
from robocram.execution.errors import ExecutionUnknownKey
from robocram.execution.process_module import ProcessModule
from robocram.execution.process_module_matching import (
    install_process_module_interface,
    process_modules_running,
)
from robocram.logic import KnowledgeBase, using_kb


class Environment:
    """A named set of process modules, facts and variables to run plans in.

    Args:
        name: a label, also the fact group name of ``facts``.
        process_modules: the modules started while the environment is entered.
        facts: Prolog text loaded into the knowledge base as group ``<name>_facts``.
        kb: the knowledge base to use (a fresh one by default); it gets the designator
            predicates and the process module interface.
        location_resolver: bound as the current location resolver (default: pose only).
        variables: context variables and the values they take inside the environment.
    """

    def __init__(
        self,
        name: str,
        process_modules: Iterable[ProcessModule] = (),
        facts: str = "",
        kb: KnowledgeBase | None = None,
        location_resolver: LocationResolver | None = None,
        variables: Mapping[contextvars.ContextVar[Any], Any] | None = None,
    ) -> None:
        self.name = name
        self.process_modules = tuple(process_modules)
        self.kb = kb if kb is not None else KnowledgeBase()
        self.location_resolver = location_resolver or LocationResolver()
        self.variables = dict(variables or {})
        install_designator_predicates(self.kb)
        install_process_module_interface(self.kb)
        if facts:
            self.kb.consult(facts, group=f"{name}_facts")
        self._stacks: list[ExitStack] = []
        self._lock = threading.Lock()

    def __repr__(self) -> str:
        modules = [m.name for m in self.process_modules]
        return f"<Environment {self.name!r} modules={modules}>"

    def module(self, name: str) -> ProcessModule:
        """Return this environment's process module called ``name``."""
        for module in self.process_modules:
            if module.name == name:
                return module
        names = [m.name for m in self.process_modules]
        raise ExecutionUnknownKey(
            f"environment {self.name!r} has no process module {name!r}; it has {names}"
        )

    @contextmanager
    def running(self) -> Iterator[Environment]:
        """Switch the environment on for the block (KB, resolver, variables, modules)."""
        with ExitStack() as stack:
            stack.enter_context(using_kb(self.kb))
            stack.enter_context(using_location_resolver(self.location_resolver))
            for variable, value in self.variables.items():
                token = variable.set(value)
                stack.callback(variable.reset, token)
            stack.enter_context(process_modules_running(*self.process_modules))
            yield self

    def __enter__(self) -> Environment:
        stack = ExitStack()
        stack.enter_context(self.running())
        with self._lock:
            self._stacks.append(stack)
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        with self._lock:
            stack = self._stacks.pop()
        stack.close()

"""Which running process module handles a designator, decided by the knowledge base.

``matching_process_module(Desig, PM)`` and ``available_process_module(PM)`` are interface
predicates: they fail until a robot or environment extends them with facts or rules
naming modules by their ``name`` atom. ``motion_process_module(Type, Prefix, PM)`` is the
table an environment's motion modules are matched through (see ``matching_facts``).
``process_modules_running(...)`` starts modules for a block (CRAM's
``with-process-modules-running``) and binds them as running in this context; PERFORM
only sends commands to modules that are matching, available and running.
"""

from __future__ import annotations

import contextvars
from collections.abc import Iterator
from contextlib import contextmanager

from robocram.execution.errors import ExecutionArgumentError, ExecutionUsageError
from robocram.execution.process_module import ProcessModule
from robocram.logic import KnowledgeBase

INTERFACE_GROUP = "process_module_interface"
_INTERFACE_TEXT = """
matching_process_module(_, _) :- fail.
available_process_module(_) :- fail.
motion_process_module(_, _, _) :- fail.
"""
INTERFACE_PREDICATES = (
    "matching_process_module/2",
    "available_process_module/1",
    "motion_process_module/3",
)

_RUNNING: contextvars.ContextVar[tuple[ProcessModule, ...]] = contextvars.ContextVar(
    "robocram_running_process_modules", default=()
)


def install_process_module_interface(kb: KnowledgeBase) -> KnowledgeBase:
    """Declare the matching interface predicates in ``kb`` (idempotent); return ``kb``."""
    if not all(kb.defines(p) for p in INTERFACE_PREDICATES):
        kb.consult(_INTERFACE_TEXT, group=INTERFACE_GROUP, extendable=INTERFACE_PREDICATES)
    return kb


def running_process_modules() -> tuple[ProcessModule, ...]:
    """Return the process modules running in this context, outermost first."""
    return _RUNNING.get()


@contextmanager
def process_modules_running(*modules: ProcessModule) -> Iterator[tuple[ProcessModule, ...]]:
    """Start ``modules`` for the block and stop them after (those this block started).

    Modules already running (an outer block started them) are shared, not restarted.
    """
    outer = _RUNNING.get()
    for module in modules:
        if not isinstance(module, ProcessModule):
            raise ExecutionUsageError(
                f"process_modules_running takes ProcessModule instances, got {module!r}"
            )
        clash = next((m for m in outer if m.name == module.name and m is not module), None)
        if clash is not None:
            raise ExecutionArgumentError(
                f"process module name {module.name!r} is already taken by running {clash!r}; "
                "give each module of an environment its own name"
            )
    started: list[ProcessModule] = []
    try:
        for module in modules:
            if not module.running:
                module.start()
                started.append(module)
        fresh = tuple(m for m in dict.fromkeys(modules) if m not in outer)
        token = _RUNNING.set(outer + fresh)
        try:
            yield outer + fresh
        finally:
            _RUNNING.reset(token)
    finally:
        for module in reversed(started):
            module.stop()


def matching_process_modules(designator: object, kb: KnowledgeBase) -> list[ProcessModule]:
    """Return the running modules that ``kb`` says match ``designator`` and are available."""
    by_name = {module.name: module for module in _RUNNING.get()}
    found: dict[str, ProcessModule] = {}
    query = "matching_process_module(D, PM), available_process_module(PM)"
    for answer in kb.query(query, D=designator):
        module = by_name.get(answer["PM"])
        if module is not None and module.running:
            found.setdefault(module.name, module)
    return list(found.values())

"""PERFORM: the one entry from plans to the robot, the same call on any robot or world.

A motion designator is grounded to a command (``motion_grounding/2``) and sent to the
running process modules that the knowledge base matches with it, first one first; if all
fail, the first failure is re-raised (CRAM's semantics). An action designator is grounded
to a plan (``action_grounding/2``): a Python callable, or a term ``name(Args...)`` whose
name was given to :func:`register_plan`; PERFORM calls it. Each PERFORM is a child task
``perform <type>`` of the current task and a stop point before and after its command.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

from robocram.designators import (
    ActionDesignator,
    Designator,
    DesignatorError,
    MotionDesignator,
    bound_kb,
)
from robocram.execution.failures import (
    DesignatorFailure,
    DesignatorReferenceFailure,
    NoMatchingProcessModule,
    PlanFailure,
)
from robocram.execution.process_module_matching import (
    matching_process_modules,
    running_process_modules,
)
from robocram.execution.task_context import checkpoint, sub_task
from robocram.execution.task_listeners import notify_performing
from robocram.logic import KnowledgeBase, Term

PLAN_INTERFACE_GROUP = "plan_interface"
T = TypeVar("T")


def perform(designator: Designator, kb: KnowledgeBase | None = None) -> Any:
    """Execute a motion or action designator in ``kb`` (default: the current one).

    Raises:
        DesignatorReferenceFailure: the designator has no grounding.
        NoMatchingProcessModule: no running module matches the motion.
        PlanFailure: what the module or plan raised, with module and command named.
    """
    if not isinstance(designator, (MotionDesignator, ActionDesignator)):
        raise DesignatorFailure(
            f"perform takes motion or action designators, got {designator!r}; locations and "
            "objects are arguments of motions and actions",
            designator=designator,
        )
    with sub_task(f"perform {designator.type}") as task:
        notify_performing(task, designator)
        checkpoint()
        knowledge = _knowledge_base(designator, kb)
        grounding = _reference(designator, knowledge)
        if isinstance(designator, MotionDesignator):
            task.result = _send(designator, grounding, knowledge)
        else:
            task.result = _run_plan(designator, grounding, knowledge)
        checkpoint()
        return task.result


def perform_plan(designator: ActionDesignator, plan: Callable[[], T]) -> T:
    """Perform ``designator`` by calling ``plan()``: a typed action table's plain call.

    The same child task ``perform <type>``, listener notice and stop points as
    :func:`perform`, without grounding in a knowledge base; ``robocram.plans.perform`` runs
    the action types of its table this way, so the call can be followed in the code.
    """
    with sub_task(f"perform {designator.type}") as task:
        notify_performing(task, designator)
        checkpoint()
        result = plan()
        task.result = result
        checkpoint()
        return result


def _knowledge_base(designator: Designator, kb: KnowledgeBase | None) -> KnowledgeBase:
    knowledge = kb if kb is not None else bound_kb()
    if knowledge is None:
        raise DesignatorReferenceFailure(
            f"cannot perform {designator.description}: no knowledge base; run it inside an "
            "environment (with env: ...) or pass perform(d, kb=...)",
            designator=designator,
        )
    return knowledge


def _reference(designator: Designator, kb: KnowledgeBase) -> Any:
    try:
        return designator.reference(kb)
    except DesignatorError as err:
        blame = {k: v for k in ("occluded_by", "blocked_by") if (v := getattr(err, k, None))}
        raise DesignatorReferenceFailure(str(err), designator=designator, **blame) from err


def _send(designator: Designator, command: object, kb: KnowledgeBase) -> Any:
    modules = matching_process_modules(designator, kb)
    if not modules:
        running = [m.name for m in running_process_modules()]
        raise NoMatchingProcessModule(
            f"no running process module matches {designator.description} (command {command}); "
            f"running: {running}",
            designator=designator,
            running=running,
        )
    failures: list[PlanFailure] = []
    for module in modules:
        try:
            return module.call(command)
        except PlanFailure as failure:
            failures.append(failure)
    raise failures[0]  # every matching module failed: the first one's reason


def _run_plan(designator: Designator, plan: object, kb: KnowledgeBase) -> Any:
    if callable(plan) and not isinstance(plan, Term):
        return plan()
    if isinstance(plan, Term):
        registered = _registered_plans(kb)
        if plan.name in registered:
            return registered[plan.name](*plan.args)
        raise DesignatorReferenceFailure(
            f"{designator.description} grounds to plan {plan}, but no plan function is "
            f"registered as {plan.name!r}; registered: {sorted(registered)}; "
            "use register_plan(kb, name, fn)",
            designator=designator,
        )
    raise DesignatorReferenceFailure(
        f"{designator.description} grounds to {plan!r}, which is neither a callable nor a "
        "term naming a registered plan",
        designator=designator,
    )


def _registered_plans(kb: KnowledgeBase) -> dict[str, Callable[..., object]]:
    if not kb.defines("plan_function/2"):
        return {}
    return {a["Name"]: a["F"] for a in kb.query("plan_function(Name, F)")}


def register_plan(kb: KnowledgeBase, name: str, function: Callable[..., object]) -> None:
    """Let action groundings name ``function`` as ``name(Args...)`` in ``kb``."""
    if not callable(function):
        raise TypeError(f"register_plan({name!r}) needs a callable, got {function!r}")
    if not kb.defines("plan_function/2"):
        kb.consult(
            "plan_function(_, _) :- fail.",
            group=PLAN_INTERFACE_GROUP,
            extendable=["plan_function/2"],
        )
    kb.add_fact_group(f"plan_{name}", [Term("plan_function", (name, function))])

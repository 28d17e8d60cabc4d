"""PERFORM: the one entry from plans to the robot, the same call on any robot or world.

An action designator whose type is in the action table (``perform(d, actions)``, else the
default: ``robocram.plans.ACTIONS`` once ``robocram.plans`` is imported) runs its plan by a
plain Python call, its keys checked first (:mod:`~robocram.execution.action_table`). Any
other designator is grounded in the knowledge base: a motion to a command
(``motion_grounding/2``) sent to the running process modules that the knowledge base
matches with it, first one first; if all fail, the first failure is re-raised (CRAM's
semantics). An action to a plan (``action_grounding/2``): a Python callable, or a term
``name(Args...)`` whose name was given to :func:`register_plan`; PERFORM calls it. Each
PERFORM is a child task ``perform <type>`` of the current task and a stop point before
and after its command.
"""

from __future__ import annotations

import difflib
from collections.abc import Callable
from typing import Any, TypeVar

from robocram.designators import (
    ActionDesignator,
    Designator,
    DesignatorError,
    MotionDesignator,
    bound_kb,
)
from robocram.designators.errors import GroundingError
from robocram.execution.action_table import ActionTable, default_actions
from robocram.execution.errors import ExecutionUsageError
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
TABLE_PLAN = "robocram_action"  # the plan term install_actions grounds a table's types to
T = TypeVar("T")


def perform(
    designator: Designator,
    actions: ActionTable | None = None,
    *,
    kb: KnowledgeBase | None = None,
) -> Any:
    """Execute a motion or action designator: an action of ``actions`` (default:
    :func:`~robocram.execution.action_table.default_actions`) by its plan, anything else
    grounded in ``kb`` (default: the current one). The result is what the plan or the
    process module returns (an action type names it: ``ActionType.result``).

    Raises:
        DesignatorPropertyError: a key the action type does not know, or one it needs
            left out.
        DesignatorReferenceFailure: the designator has no grounding (a misspelled action
            type: the closest and every known type are named).
        NoMatchingProcessModule: no running module matches the motion.
        PlanFailure: what the module or plan raised, with module and command named.
    """
    if not isinstance(designator, (MotionDesignator, ActionDesignator)):
        raise DesignatorFailure(
            f"perform takes motion or action designators, got {designator!r}; locations and "
            "objects are arguments of motions and actions",
            designator=designator,
        )
    table = actions if actions is not None else default_actions()
    if (
        isinstance(designator, ActionDesignator)
        and designator.type in table
        and not _grounded_by_own_rule(designator, kb)
    ):
        action = table[designator.type]
        return perform_plan(designator, lambda: action.run(designator))
    try:
        return _perform_grounded(designator, kb)
    except DesignatorReferenceFailure as failure:
        unknown = _unknown_action(designator, table, failure)
        if unknown is None:
            raise
        raise unknown from failure


def _perform_grounded(designator: Designator, kb: KnowledgeBase | None) -> object:
    """PERFORM by the knowledge base's grounding rules."""
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
    """Perform ``designator`` by calling ``plan()``: an action table's plain call.

    The same child task ``perform <type>``, listener notice and stop points as a grounded
    PERFORM, without a knowledge base: :func:`perform` runs the action types of its table
    this way, so the call can be followed in the code.
    """
    with sub_task(f"perform {designator.type}") as task:
        notify_performing(task, designator)
        checkpoint()
        result = plan()
        task.result = result
        checkpoint()
        return result


def _grounded_by_own_rule(designator: ActionDesignator, kb: KnowledgeBase | None) -> bool:
    """Whether the knowledge base's first grounding of ``designator`` is a rule of its own
    (a turtle's ``navigating``), which wins over the table's plan: CRAM grounds actions in
    Prolog, the table is the default for the types no environment or robot defines."""
    knowledge = kb if kb is not None else bound_kb()
    if knowledge is None or not knowledge.defines("action_grounding/2"):
        return False
    for answer in knowledge.query("action_grounding(D, G)", D=designator):
        plan = answer["G"]
        return not (isinstance(plan, Term) and plan.name == TABLE_PLAN)
    return False


def _unknown_action(
    designator: Designator, table: ActionTable, failure: DesignatorReferenceFailure
) -> DesignatorReferenceFailure | None:
    """For an action whose type neither the table nor the KB's rules know: the failure
    naming every known type and the closest (a misspelling), else None."""
    cause = failure.__cause__
    if not isinstance(designator, ActionDesignator) or not isinstance(cause, GroundingError):
        return None
    known = sorted({*table, *cause.grounded_types})
    if designator.type in known:
        return None
    close = difflib.get_close_matches(str(designator.type), known, n=1)
    hint = f"did you mean {close[0]!r}? " if close else ""
    return DesignatorReferenceFailure(
        f"no action type {designator.type!r}; {hint}known types: {', '.join(known) or 'none'}"
        + ("" if table.types else " (import robocram.plans for its action types)"),
        designator=designator,
    )


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
        raise ExecutionUsageError(f"register_plan({name!r}) needs a callable, got {function!r}")
    if not kb.defines("plan_function/2"):
        kb.consult(
            "plan_function(_, _) :- fail.",
            group=PLAN_INTERFACE_GROUP,
            extendable=["plan_function/2"],
        )
    kb.add_fact_group(f"plan_{name}", [Term("plan_function", (name, function))])

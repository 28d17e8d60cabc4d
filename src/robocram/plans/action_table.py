"""The action table: each action type robocram's plans understand, and its plan function.

The table is the one place an action type is described (:class:`ActionType`: required
and optional keys, plan). From it come:

- :func:`perform`: PERFORM with the table. An action of the table runs its plan by a plain
  Python call, ``ACTIONS["transporting"].plan`` is :func:`~robocram.plans.transport.transport`,
  so a reader and an IDE follow ``perform(an.action(type="transporting", ...))`` to the
  plan without reading Prolog; anything else goes to :func:`robocram.execution.perform`.
- :func:`install_actions`: the ``action_grounding/2`` rule and ``robocram_action_type/1``
  facts written from the table, for users who reason about actions in Prolog or perform
  them with :func:`robocram.execution.perform`.

A user adds an action type with one registration, ``ACTIONS.adding(ActionType(...))``, a new
table passed to :func:`perform` and :func:`install_actions` (docs/transport.md).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from robocram.designators import ActionDesignator, Designator, install_designator_predicates
from robocram.designators.errors import GroundingError
from robocram.execution import perform as perform_designator
from robocram.execution import perform_plan, register_plan
from robocram.execution.failures import DesignatorReferenceFailure
from robocram.logic import KnowledgeBase, Term
from robocram.plans.action_type import ActionType
from robocram.plans.basic_actions import (
    detect,
    look,
    move_torso,
    navigate,
    park_arms,
    set_gripper,
)
from robocram.plans.containers import close_container, open_container
from robocram.plans.deliver import deliver
from robocram.plans.fetch import fetch
from robocram.plans.pick_object import pick_up_object
from robocram.plans.place_object import place_object
from robocram.plans.search import search
from robocram.plans.transport import transport

ACTIONS_GROUP = "robocram_actions"
GROUNDING_RULE = (
    "action_grounding(D, robocram_action(D)) :-\n"
    "    action_desig(D), desig_prop(D, type, T), robocram_action_type(T).\n"
)


@dataclass(frozen=True)
class ActionTable:
    """Action types by their ``type``; immutable, extended by :meth:`adding`."""

    types: Mapping[str, ActionType]

    @classmethod
    def of(cls, *types: ActionType) -> ActionTable:
        """A table of ``types``; a type named twice is refused."""
        return cls(MappingProxyType({})).adding(*types)

    def adding(self, *types: ActionType) -> ActionTable:
        """This table with ``types`` added (the one registration of a new action type)."""
        found = dict(self.types)
        for t in types:
            if t.type in found:
                raise ValueError(f"action type {t.type!r} is already in the table")
            found[t.type] = t
        return ActionTable(MappingProxyType(found))

    def __getitem__(self, type_: str) -> ActionType:
        return self.types[type_]

    def __contains__(self, type_: object) -> bool:
        return type_ in self.types

    def __iter__(self) -> Iterator[str]:
        return iter(self.types)

    def facts(self) -> list[Term]:
        """``robocram_action_type(T)`` for every type of the table."""
        return [Term("robocram_action_type", (t,)) for t in self.types]


ACTIONS = ActionTable.of(
    ActionType("navigating", ("target",), (), navigate),
    ActionType("looking", ("target",), (), look),
    ActionType("detecting", ("object",), (), detect),
    ActionType("searching", ("object",), ("poses_per_place",), search),
    ActionType("parking-arms", (), ("arm",), park_arms),
    ActionType("moving-torso", ("joint_angle",), (), move_torso),
    ActionType("setting-gripper", ("gripper", "motion"), (), set_gripper),
    ActionType("opening", ("object",), ("arm", "distance", "angle"), open_container),
    ActionType("closing", ("object",), ("arm",), close_container),
    ActionType("picking-up", ("object",), ("arm", "grasp"), pick_up_object),
    ActionType("placing", ("object", "target"), ("arm",), place_object),
    ActionType("fetching", ("object",), ("arm", "grasp", "stand_retries"), fetch),
    ActionType(
        "delivering", ("object", "target"), ("arm", "stand_retries", "place_retries"), deliver
    ),
    ActionType(
        "transporting",
        ("object", "target"),
        ("arm", "grasp", "stand_retries", "place_retries", "placing_stands"),
        transport,
    ),
)
ACTION_TYPES: Mapping[str, ActionType] = ACTIONS.types


def perform(designator: Designator[object], actions: ActionTable = ACTIONS) -> Any:
    """PERFORM ``designator``; an action of ``actions`` runs its plan by a plain call.

    Motions, and actions of types outside the table, go to
    :func:`robocram.execution.perform` (grounded in the knowledge base).
    """
    if isinstance(designator, ActionDesignator) and designator.type in actions:
        action = actions[designator.type]
        return perform_plan(designator, lambda: action.perform(designator))
    try:
        return perform_designator(designator)
    except DesignatorReferenceFailure as failure:
        unknown = _unknown_action(designator, actions, failure)
        if unknown is None:
            raise
        raise unknown from failure


def _unknown_action(
    designator: Designator[object], actions: ActionTable, failure: DesignatorReferenceFailure
) -> DesignatorReferenceFailure | None:
    """For an action whose type neither the table nor the KB's rules know: the failure
    naming every known type and the closest (a misspelling), else None."""
    cause = failure.__cause__
    if not isinstance(designator, ActionDesignator) or not isinstance(cause, GroundingError):
        return None
    known = sorted({*actions, *cause.grounded_types})
    if designator.type in known:
        return None
    close = difflib.get_close_matches(str(designator.type), known, n=1)
    hint = f"did you mean {close[0]!r}? " if close else ""
    return DesignatorReferenceFailure(
        f"no action type {designator.type!r}; {hint}known types: {', '.join(known)}",
        designator=designator,
    )


def perform_action(designator: Designator[object], actions: ActionTable = ACTIONS) -> Any:
    """Run the plan of ``designator``'s action type with its checked properties."""
    return actions[str(designator.get("type"))].perform(designator)


def install_actions(kb: KnowledgeBase, actions: ActionTable = ACTIONS) -> KnowledgeBase:
    """Ground the action types of ``actions`` in ``kb`` to their plans, in Prolog."""
    install_designator_predicates(kb)
    kb.add_fact_group(ACTIONS_GROUP, [*actions.facts(), GROUNDING_RULE])
    register_plan(kb, "robocram_action", lambda d: perform_action(d, actions))
    return kb

"""The action designators robocram plans understand, in CRAM's vocabulary.

``install_actions(kb)`` adds one ``action_grounding/2`` rule that grounds every action
designator whose ``type`` is in :data:`ACTION_TYPES` to the registered plan
``robocram_action(D)``; that plan checks the designator's keys
(:meth:`ActionType.arguments`) and runs the type's plan function. So
``perform(an.action(type="opening", object="drawer_unit_drawer_3"))`` runs
:func:`open_container` in any environment whose KB has the actions installed.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

from robocram.designators import Designator, install_designator_predicates
from robocram.execution import register_plan
from robocram.logic import KnowledgeBase
from robocram.plans.action_type import ActionType
from robocram.plans.basic_actions import detect, look, move_torso, navigate, park_arms
from robocram.plans.containers import close_container, open_container
from robocram.plans.deliver import deliver
from robocram.plans.fetch import fetch
from robocram.plans.pick_object import pick_up_object
from robocram.plans.place_object import place_object
from robocram.plans.search import search
from robocram.plans.transport import transport

ACTIONS_GROUP = "robocram_actions"
ACTION_TYPES: Mapping[str, ActionType] = MappingProxyType(
    {
        t.type: t
        for t in (
            ActionType("navigating", ("target",), (), navigate),
            ActionType("looking", ("target",), (), look),
            ActionType("detecting", ("object",), (), detect),
            ActionType("searching", ("object",), ("poses_per_place",), search),
            ActionType("parking-arms", (), ("arm",), park_arms),
            ActionType("moving-torso", ("joint_angle",), (), move_torso),
            ActionType("opening", ("object",), ("arm", "distance", "angle"), open_container),
            ActionType("closing", ("object",), ("arm",), close_container),
            ActionType("picking-up", ("object",), ("arm", "grasp"), pick_up_object),
            ActionType("placing", ("object", "target"), ("arm",), place_object),
            ActionType("fetching", ("object",), ("arm", "grasp", "stand_retries"), fetch),
            ActionType(
                "delivering",
                ("object", "target"),
                ("arm", "stand_retries", "place_retries"),
                deliver,
            ),
            ActionType(
                "transporting",
                ("object", "target"),
                ("arm", "grasp", "stand_retries", "place_retries", "placing_stands"),
                transport,
            ),
        )
    }
)


def perform_action(designator: Designator[Any]) -> Any:
    """Run the plan of ``designator``'s action type with its checked properties."""
    return ACTION_TYPES[str(designator.get("type"))].perform(designator)


def install_actions(kb: KnowledgeBase) -> KnowledgeBase:
    """Ground the action types of :data:`ACTION_TYPES` in ``kb`` to their plans."""
    install_designator_predicates(kb)
    types = "\n".join(f"robocram_action_type('{t}')." for t in ACTION_TYPES)
    rule = (
        "action_grounding(D, robocram_action(D)) :-\n"
        "    action_desig(D), desig_prop(D, type, T), robocram_action_type(T).\n"
    )
    kb.consult(types + "\n" + rule, group=ACTIONS_GROUP)
    register_plan(kb, "robocram_action", perform_action)
    return kb

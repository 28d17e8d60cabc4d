"""The action table: each action type robocram's plans understand, and its plan function.

The table is the one place an action type is described (:class:`ActionType`: required
and optional keys, plan, result). From it come:

- PERFORM's default table (:func:`robocram.execution.perform`, also ``robocram.plans.perform``):
  once this module is imported, an action of the table runs its plan by a plain Python
  call, ``ACTIONS["transporting"].plan`` is :func:`~robocram.plans.transport.transport`, so
  a reader and an IDE follow ``perform(an.action(type="transporting", ...))`` to the plan
  without reading Prolog;
- :func:`install_actions`: the ``action_grounding/2`` rule and ``robocram_action_type/1``
  facts written from the table, for users who reason about actions in Prolog.

A user adds an action type with one registration, ``ACTIONS.adding(ActionType(...))``, a new
table passed to ``perform(d, table)`` and :func:`install_actions` (docs/transport.md).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from robocram.designators import Designator, install_designator_predicates
from robocram.execution import register_plan
from robocram.execution.action_table import ActionTable, use_default_actions
from robocram.execution.action_type import ActionType
from robocram.execution.perform import TABLE_PLAN
from robocram.logic import KnowledgeBase
from robocram.plans.basic_actions import (
    detect,
    look,
    move_torso,
    navigate,
    park_arms,
    set_gripper,
)
from robocram.plans.carrying import carry
from robocram.plans.clearing_table import clear_table
from robocram.plans.containers import close_container, open_container
from robocram.plans.deliver import deliver
from robocram.plans.facing import face
from robocram.plans.fetch import fetch
from robocram.plans.pick_object import grasp_object, pick_up_object
from robocram.plans.place_object import place_object
from robocram.plans.search import search
from robocram.plans.setting_table import set_table
from robocram.plans.tool_actions import cut, mix, pour, wipe
from robocram.plans.transport import transport

ACTIONS_GROUP = "robocram_actions"
GROUNDING_RULE = (
    f"action_grounding(D, {TABLE_PLAN}(D)) :-\n"
    "    action_desig(D), desig_prop(D, type, T), robocram_action_type(T).\n"
)


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
    ActionType("grasping", ("object",), ("arm", "grasp"), grasp_object),
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
    ActionType("pouring", ("source", "target", "amount"), ("arm",), pour),
    ActionType("wiping", ("surface", "region", "tool"), ("arm",), wipe),
    ActionType("cutting", ("object", "tool", "slices"), ("arm",), cut),
    ActionType("mixing", ("container", "tool"), ("arm", "turns"), mix),
    ActionType(
        "setting-table", (), ("people", "table", "setting", "shared", "two_arms"), set_table
    ),
    ActionType("clearing-table", (), ("table", "objects"), clear_table),
    ActionType("facing", ("target",), (), face),
    ActionType("carrying", (), ("target", "arm"), carry),
)
ACTION_TYPES: Mapping[str, ActionType] = ACTIONS.types
use_default_actions(ACTIONS)  # PERFORM runs these by their plans wherever plans are imported


def perform_action(designator: Designator[object], actions: ActionTable = ACTIONS) -> Any:
    """Run the plan of ``designator``'s action type with its checked properties."""
    return actions[str(designator.get("type"))].run(designator)


def install_actions(kb: KnowledgeBase, actions: ActionTable = ACTIONS) -> KnowledgeBase:
    """Ground the action types of ``actions`` in ``kb`` to their plans, in Prolog."""
    install_designator_predicates(kb)
    kb.add_fact_group(ACTIONS_GROUP, [*actions.facts(), GROUNDING_RULE])
    register_plan(kb, TABLE_PLAN, lambda d: perform_action(d, actions))
    return kb

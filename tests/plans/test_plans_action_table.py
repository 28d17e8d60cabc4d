"""The action table: one registration per action type, plans reached by a plain call."""

from __future__ import annotations

import ast
import importlib
from pathlib import Path

import pytest

from robocram.designators import DesignatorPropertyError, an
from robocram.execution import perform as perform_in_kb
from robocram.execution import top_level
from robocram.logic import KnowledgeBase
from robocram.plans import ACTIONS, ActionType, install_actions, perform
from robocram.plans.transport import transport

SRC = Path(__file__).resolve().parents[2] / "src" / "robocram"


def _action_type_calls() -> list[tuple[str, str]]:
    """(file, type) of every ``ActionType("type", ...)`` written in the sources."""
    found = []
    for path in sorted(SRC.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (
                isinstance(node, ast.Call)
                and isinstance(node.func, ast.Name)
                and node.func.id == "ActionType"
                and node.args
                and isinstance(node.args[0], ast.Constant)
            ):
                found.append((str(path.relative_to(SRC)), str(node.args[0].value)))
    return found


def test_every_action_type_is_registered_once_in_one_place() -> None:
    calls = _action_type_calls()
    assert {file for file, _ in calls} == {"plans/action_table.py"}
    assert sorted(t for _, t in calls) == sorted(ACTIONS)


@pytest.mark.parametrize("type_", list(ACTIONS), ids=str)
def test_each_plan_is_importable_by_its_name(type_: str) -> None:
    plan = ACTIONS[type_].plan
    assert getattr(importlib.import_module(plan.__module__), plan.__name__) is plan


def test_transporting_is_the_transport_plan() -> None:
    assert ACTIONS["transporting"].plan is transport


def _count(object: str, times: int = 1) -> str:  # noqa: A002 - the designator's key
    return object * times


COUNTING = ActionType("counting", ("object",), ("times",), _count)


def test_one_registration_adds_a_type_that_perform_calls_directly() -> None:
    actions = ACTIONS.adding(COUNTING)
    with top_level() as tl:
        assert perform(an.action(type="counting", object="ab", times=3), actions) == "ababab"
    assert [t.name for t in tl.tree.snapshot().children] == ["perform counting"]
    with pytest.raises(ValueError, match="'counting' is already in the table"):
        actions.adding(COUNTING)


def test_the_prolog_grounding_rule_is_written_from_the_table() -> None:
    kb = install_actions(KnowledgeBase(), ACTIONS.adding(COUNTING))
    types = {str(a["T"]) for a in kb.query("robocram_action_type(T)")}
    assert types == set(ACTIONS) | {"counting"}
    with top_level():
        assert perform_in_kb(an.action(type="counting", object="x", times=2), kb=kb) == "xx"
        with pytest.raises(DesignatorPropertyError, match="no key 'size'"):
            perform_in_kb(an.action(type="counting", object="x", size=2), kb=kb)


def test_there_is_one_perform_and_each_type_names_its_result() -> None:
    from robocram import execution, plans
    from robocram.plans.transport import TransportResult

    assert plans.perform is execution.perform
    assert ACTIONS["transporting"].result is TransportResult
    assert ACTIONS["picking-up"].result is plans.Held


def test_a_type_the_knowledge_base_grounds_by_its_own_rule_is_performed_by_that_rule() -> None:
    """As the turtle's ``navigating``: the KB's first grounding decides (CRAM's way)."""
    from robocram.designators import install_designator_predicates

    kb = install_designator_predicates(KnowledgeBase())
    kb.consult(
        "action_grounding(D, own_navigation(D)) :-\n"
        "    action_desig(D), desig_prop(D, type, navigating).",
        group="own",
    )
    ran: list[object] = []
    from robocram.execution import register_plan

    register_plan(kb, "own_navigation", lambda d: ran.append(d) or "own")
    with top_level():
        assert perform_in_kb(an.action(type="navigating", target=(1, 2)), kb=kb) == "own"
    assert len(ran) == 1

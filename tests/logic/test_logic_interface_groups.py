"""CRAM's interface idiom: one group declares predicates extendable, many groups extend them."""

from __future__ import annotations

import pytest

from robocram.logic import FactGroupError, KnowledgeBase


def test_a_declared_interface_predicate_fails_instead_of_being_unknown() -> None:
    kb = KnowledgeBase()
    kb.add_fact_group("robot_interface", [], extendable=["robot/1"])
    assert kb.holds("robot(pr2)") is False


def test_many_groups_extend_an_interface_and_reloading_one_replaces_only_its_clauses() -> None:
    kb = KnowledgeBase()
    kb.add_fact_group("robot_interface", [], extendable=["robot/1"])
    kb.consult("robot(pr2).", group="pr2_description")
    kb.consult("robot(hsrb).", group="hsrb_description")
    kb.consult("robot(boxy).", group="boxy_description")
    kb.consult("robot(pr2). robot(pr2_copy).", group="pr2_description")
    assert sorted(a["R"] for a in kb.query("robot(R)")) == ["boxy", "hsrb", "pr2", "pr2_copy"]


def test_a_predicate_nobody_declared_extendable_stays_with_its_owner() -> None:
    kb = KnowledgeBase()
    kb.consult("colour(red).", group="palette")
    with pytest.raises(FactGroupError, match="colour/1"):
        kb.consult("colour(blue).", group="other")

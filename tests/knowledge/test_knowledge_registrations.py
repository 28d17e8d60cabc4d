"""The table registers exactly the world's and the grasp model's predicates, one by one.

Before the switch, tests/knowledge/test_knowledge_table_matches_code.py compared the
table with the hand-written ``kb.predicate(...)`` calls; now the table makes them, and
these tests compare what a knowledge base ends up with.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.grasping import install_grasp_predicates
from robocram.knowledge import (
    PREDICATE_TABLE,
    ImplementationMismatch,
    Source,
    indicators_of,
    predicates_of,
    register_predicates,
)
from robocram.logic import KnowledgeBase
from robocram.robots import load_description
from robocram.robots.interface_facts import INTERFACE_PREDICATES, description_facts
from robocram.world import World


@pytest.fixture(scope="module")
def world_kb() -> Iterator[KnowledgeBase]:
    world = World()
    try:
        yield world.kb
    finally:
        world.close()


def _added(kb: KnowledgeBase) -> set[str]:
    return set(kb.predicates()) - set(KnowledgeBase().predicates())


@pytest.mark.parametrize("indicator", [p.indicator for p in predicates_of(Source.WORLD)])
def test_each_world_row_is_registered(world_kb: KnowledgeBase, indicator: str) -> None:
    assert indicator in world_kb.predicates()


def test_the_world_registers_nothing_but_its_rows(world_kb: KnowledgeBase) -> None:
    assert _added(world_kb) == set(indicators_of(Source.WORLD))


@pytest.mark.parametrize("indicator", indicators_of(Source.GRASPING))
def test_each_grasp_row_is_registered(indicator: str) -> None:
    assert indicator in install_grasp_predicates(KnowledgeBase()).predicates()


def test_a_row_without_implementation_is_refused_by_name() -> None:
    kb = KnowledgeBase()
    with pytest.raises(ImplementationMismatch) as caught:
        register_predicates(kb, Source.GRASPING, {"grasping_arm/2": iter, "grip/9": iter})
    assert caught.value.missing == [
        "object_extent/3",
        "object_grasp/7",
        "object_ungraspable/5",
    ]
    assert caught.value.unknown == ["grip/9"]
    assert "grasping_arm/2" not in kb.predicates()  # nothing registered on a mismatch


def test_the_interface_predicates_are_the_description_rows() -> None:
    assert indicators_of(Source.DESCRIPTION) == INTERFACE_PREDICATES
    assert len(INTERFACE_PREDICATES) == 36  # arm_working_direction/3 the last added


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy", "quadrotor"])
def test_every_description_fact_round_trips_through_its_row(robot: str) -> None:
    for fact in description_facts(load_description(robot)):
        p = PREDICATE_TABLE[f"{fact.name}/{fact.arity}"]
        assert p.source is Source.DESCRIPTION
        row = p.row(**{a.name: a.convert(v) for a, v in zip(p.arguments, fact.args, strict=True)})
        assert p.fact(row) == fact

"""The predicate table against the registrations written by hand, predicate by predicate."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from robocram.knowledge import PREDICATE_TABLE, Source, indicators_of, predicates_of
from robocram.robots import load_description
from robocram.robots.interface_facts import INTERFACE_PREDICATES, description_facts

SRC = Path(__file__).resolve().parents[2] / "src" / "robocram"
HAND_WRITTEN = {
    Source.WORLD: SRC / "world" / "predicates.py",
    Source.GRASPING: SRC / "grasping" / "grasp_predicates.py",
}


def _registered(path: Path) -> set[str]:
    """``name/arity`` of every ``kb.predicate(...)`` and ``kb.add_predicate(...)`` call."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr in {"predicate", "add_predicate"}
            and len(node.args) >= 2
            and isinstance(node.args[0], ast.Constant)
            and isinstance(node.args[1], ast.Constant)
        ):
            found.add(f"{node.args[0].value}/{node.args[1].value}")
    return found


@pytest.mark.parametrize(
    "indicator",
    [p.indicator for s in HAND_WRITTEN for p in predicates_of(s)],
)
def test_each_computed_predicate_is_registered_by_hand(indicator: str) -> None:
    source = PREDICATE_TABLE[indicator].source
    assert indicator in _registered(HAND_WRITTEN[source])


@pytest.mark.parametrize("source", list(HAND_WRITTEN), ids=lambda s: s.value)
def test_nothing_registered_by_hand_is_left_out_of_the_table(source: Source) -> None:
    assert _registered(HAND_WRITTEN[source]) == set(indicators_of(source))


def test_the_interface_predicates_are_the_description_rows() -> None:
    assert tuple(sorted(INTERFACE_PREDICATES)) == indicators_of(Source.DESCRIPTION)


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy", "quadrotor"])
def test_every_description_fact_is_a_row_of_the_table(robot: str) -> None:
    for fact in description_facts(load_description(robot)):
        p = PREDICATE_TABLE[f"{fact.name}/{fact.arity}"]
        assert p.source is Source.DESCRIPTION
        row = p.row(**{a.name: a.convert(v) for a, v in zip(p.arguments, fact.args, strict=True)})
        assert p.fact(row) == fact

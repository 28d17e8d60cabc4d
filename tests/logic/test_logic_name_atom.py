"""Names written into facts as text read back as exactly those names (issue 42, bad 1)."""

from __future__ import annotations

import os

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robocram.logic import KnowledgeBase, name_atom

HOSTILE = (
    "t). :- retractall(supporting_surface(_, _)), assertz(pwned). %",
    "X",
    "Table_top",
    "_",
    "[]",
    "{}",
    "!",
    ";",
    ",",
    "|",
    "a\nb",
    '"""',
    "it's",
    "back\\slash",
    "/*",
    ":-",
    "is",
    "end_of_file",
    "",
    "\x00\x7f\u2028",
    "tab\there",
)
EXAMPLES = int(os.environ.get("ROBOCRAM_PROPERTY_EXAMPLES", "300"))


def read_back(name: str) -> list[object]:
    """Consult one fact written from ``name`` and return every answer of a query on it."""
    kb = KnowledgeBase()
    kb.consult(f"supporting_surface(kitchen, {name_atom(name)}).", group="names")
    assert kb.holds("supporting_surface(kitchen, L), L == N", N=name)
    return [answer["L"] for answer in kb.query("supporting_surface(kitchen, L)")]


def same_name(answer: object, name: str) -> bool:
    """The engine's atom '[]' is the empty list, which answers map to Python ``[]``."""
    return answer == name or (name == "[]" and answer == [])


@pytest.mark.parametrize("name", HOSTILE)
def test_hostile_name_stays_one_name(name: str) -> None:
    answers = read_back(name)
    assert len(answers) == 1 and same_name(answers[0], name)


def test_a_directive_in_a_name_runs_nothing() -> None:
    kb = KnowledgeBase()
    facts = [f"supporting_surface(kitchen, {name_atom(n)})." for n in ("table", HOSTILE[0])]
    kb.consult("\n".join(facts), group="kitchen")
    surfaces = [a["L"] for a in kb.query("supporting_surface(kitchen, L)")]
    assert surfaces == ["table", HOSTILE[0]]
    assert not kb.defines("pwned/0")


@settings(max_examples=EXAMPLES, deadline=None, database=None)
@given(st.text())
def test_every_string_round_trips_through_a_fact_and_a_query(name: str) -> None:
    answers = read_back(name)
    assert len(answers) == 1 and same_name(answers[0], name)


def test_a_name_must_be_text() -> None:
    with pytest.raises(TypeError, match="must be a str, not 3"):
        name_atom(3)  # type: ignore[arg-type]

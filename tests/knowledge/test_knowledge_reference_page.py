"""docs/predicates.md is the page the predicate table generates."""

from __future__ import annotations

from pathlib import Path

from robocram.knowledge import PREDICATE_TABLE
from robocram.knowledge.reference_page import reference_page

PAGE = Path(__file__).resolve().parents[2] / "docs" / "predicates.md"


def test_the_page_is_current() -> None:
    assert PAGE.read_text(encoding="utf-8") == reference_page(), (
        "regenerate: python -m robocram.knowledge.reference_page > docs/predicates.md"
    )


def test_the_page_has_one_line_per_predicate_with_units() -> None:
    text = reference_page()
    for indicator in PREDICATE_TABLE:
        assert text.count(f"| `{indicator}` |") == 1, indicator
    assert (
        "| `gripper_max_opening/3` | `Robot`: str, `Arm`: str, `Opening`: float [m] |"
        " the widest gap between the fingers. |" in text
    )

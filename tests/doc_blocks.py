"""The ``python`` blocks of a docs page, as tests/test_doc_blocks.py runs them (and a test
that runs a page's block as its own set-up: tests/plans/test_plans_activities.py)."""

from __future__ import annotations

import re
from pathlib import Path

DOCS = Path(__file__).resolve().parents[1] / "docs"
NOT_RUN = "<!-- not run by tests/test_doc_blocks.py:"


def runnable_blocks(text: str) -> list[str]:
    """The ``python`` blocks of ``text`` in order, but those marked as not run."""
    found = []
    for match in re.finditer(r"^```python\n(.*?)^```", text, flags=re.S | re.M):
        before = text[: match.start()].rstrip("\n").rsplit("\n", 1)[-1]
        if not before.startswith(NOT_RUN):
            found.append(match.group(1))
    return found

"""docs/queries.md's blocks run as written, in order, and print what the doc says."""

from __future__ import annotations

import contextlib
import io
import os
import re
import warnings
from pathlib import Path

import pytest

DOC = Path(__file__).resolve().parents[1] / "docs" / "queries.md"


def test_every_block_runs_in_order_and_counts_what_it_says(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    blocks = re.findall(r"```python\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S)
    assert len(blocks) == 4
    namespace: dict[str, object] = {"__name__": "docs_queries"}
    printed = io.StringIO()
    with warnings.catch_warnings(), contextlib.redirect_stdout(printed):
        warnings.simplefilter("ignore")
        for block in blocks:
            exec(compile(block, str(DOC), "exec"), namespace)  # noqa: S102 - the doc's own code
    out = printed.getvalue()
    assert "failed: SearchExhausted" in out
    assert "{'failed': 1, 'succeeded': 2}" in out
    assert "{'SearchExhausted': 1}" in out
    assert re.search(r"'detecting PerceptionObjectNotFound \(an object \(type mug\)\)': [1-9]", out)
    assert re.search(r"\n\S+ +\d+ x, mean +[\d.]+ ms, longest", out)
    assert os.path.getsize(tmp_path / "runs.db") > 10_000

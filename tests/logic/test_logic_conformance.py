"""Every case of benchmarks/iso_cases.pl passes on robocram (the benchmark compares SWI)."""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

from robocram.logic import KnowledgeBase

CASES = Path(__file__).resolve().parents[2] / "benchmarks" / "iso_cases.pl"


def test_iso_cases_all_pass() -> None:
    text = CASES.read_text(encoding="utf-8")
    kb = KnowledgeBase()
    kb.consult(text)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert kb.holds("iso_run")
    lines = re.findall(r"^(\d+) (pass|fail) (.*)$", out.getvalue(), re.M)
    assert len(lines) == len(re.findall(r"^case\(", text, re.M)) > 100
    assert [(i, r) for i, s, r in lines if s != "pass"] == []

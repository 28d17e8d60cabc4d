"""The canonical benchmark programs stored in benchmarks/vanroy/ run unmodified.

They are SWI-Prolog/bench's files byte for byte (the SHA-256 sums in vanroy_bench.py);
a program our reader or engine cannot run is a bug in robocram, not in the program.
"""

from __future__ import annotations

import hashlib
import importlib.util
from pathlib import Path

import pytest

from robocram.logic import KnowledgeBase

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"
STORED = sorted(p.stem for p in (BENCH / "vanroy").glob("*.pl"))


def _sums() -> dict[str, str]:
    spec = importlib.util.spec_from_file_location("vanroy_bench", BENCH / "vanroy_bench.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    sums: dict[str, str] = module.SHA256
    return sums


def test_seven_programs_are_stored() -> None:
    assert STORED == ["chat_parser", "derive", "nreverse", "qsort", "query", "serialise", "sieve"]


@pytest.mark.parametrize("name", STORED)
def test_a_stored_program_is_unmodified_and_runs(name: str) -> None:
    data = (BENCH / "vanroy" / f"{name}.pl").read_bytes()
    assert hashlib.sha256(data).hexdigest() == _sums()[name]
    kb = KnowledgeBase()
    kb.consult(data.decode("utf-8"))
    assert kb.holds("top")


def test_mode_declarations_are_accepted() -> None:
    kb = KnowledgeBase()
    kb.consult(":- mode(theorem(+, +, -)).\ntheorem(a, b, c).")
    assert kb.holds("theorem(a, b, C), C == c, mode(anything)")

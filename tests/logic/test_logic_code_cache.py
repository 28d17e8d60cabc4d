"""Compiled clause code on disk: written once, read back equal to what ``compile`` makes,
damaged or foreign files compiled again, and a knowledge base in a fresh process answers
the same from the kept code as from its own compile."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from robocram.logic.code_cache import FILENAME, compiled

SRC = Path(__file__).resolve().parents[2] / "src"
SOURCE = "def make(k):\n    def f(x):\n        return x * k + 1\n    return f\n"


@pytest.fixture
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path))
    return tmp_path / "prolog-code"


def _run(code: object) -> int:
    namespace: dict[str, object] = {}
    exec(code, namespace)  # noqa: S102
    make = namespace["make"]
    assert callable(make)
    result = make(3)(4)
    assert isinstance(result, int)
    return result


def test_written_once_and_read_back_as_compile_makes_it(folder: Path) -> None:
    first = compiled(SOURCE)
    (entry,) = folder.glob("*.code")
    written = entry.stat().st_mtime_ns
    again = compiled(SOURCE)
    assert again == compile(SOURCE, FILENAME, "exec") and first == again
    assert _run(again) == 13 and entry.stat().st_mtime_ns == written
    assert not list(folder.glob("*.tmp"))


@pytest.mark.parametrize("damage", ["cut", "flipped", "empty", "foreign"])
def test_a_damaged_or_foreign_file_is_compiled_again(folder: Path, damage: str) -> None:
    compiled(SOURCE)
    (entry,) = folder.glob("*.code")
    data = entry.read_bytes()
    if damage == "cut":
        entry.write_bytes(data[: len(data) // 2])
    elif damage == "flipped":
        entry.write_bytes(data[:-5] + bytes([data[-5] ^ 0xFF]) + data[-4:])
    elif damage == "empty":
        entry.write_bytes(b"")
    else:  # a whole, checked file that holds another source's code under this name
        other = compiled("def make(k):\n    return lambda x: -1\n")
        (other_entry,) = set(folder.glob("*.code")) - {entry}
        entry.write_bytes(other_entry.read_bytes())
        assert _run(other) == -1
    assert _run(compiled(SOURCE)) == 13
    assert entry.read_bytes() == data  # replaced by a good file


def test_an_unwritable_cache_only_compiles(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(blocker))
    assert _run(compiled(SOURCE)) == 13


def test_a_fresh_process_answers_the_same_from_kept_code(tmp_path: Path) -> None:
    query = (
        "from robocram.logic import KnowledgeBase\n"
        "kb = KnowledgeBase()\n"
        "kb.consult('len([], 0).\\nlen([_|T], N) :- len(T, M), N is M + 1.\\n"
        "pick(X) :- member(X, [c, a, b]), X @> a.')\n"
        "print(list(kb.query('len([a, b, c], N)')), list(kb.query('pick(X)')))\n"
    )
    env = {**os.environ, "ROBOCRAM_CACHE_DIR": str(tmp_path), "PYTHONPATH": str(SRC)}
    answers = [
        subprocess.run(
            [sys.executable, "-c", query], capture_output=True, text=True, check=True, env=env
        ).stdout
        for _ in range(2)
    ]
    assert answers[0] == answers[1] == "[{'N': 3}] [{'X': 'c'}, {'X': 'b'}]\n"
    assert list((tmp_path / "prolog-code").glob("*.code"))

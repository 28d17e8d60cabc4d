"""A script that starts a process batch outside its main guard is refused at once, in one
line naming the script, the line and the fix, before any worker is spawned (issue 41:
docs/batch.md's first block, saved as a script, came back with every variant LOST)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from robocram.batch.main_guard import _guarded

BATCH = "from robocram.batch import Variant, project_variants\n"


def _run(tmp_path: Path, text: str) -> subprocess.CompletedProcess[str]:
    script = tmp_path / "my_batch.py"
    script.write_text(text, encoding="utf-8")
    return subprocess.run(
        [sys.executable, str(script)], capture_output=True, text=True, timeout=120, check=False
    )


@pytest.mark.parametrize(
    "body, line",
    [
        ("for r in project_variants([Variant('a')], workers=1):\n    print(r)\n", 2),
        (
            "def main():\n    return list(project_variants([Variant('a')], workers=1))\n\nmain()\n",
            5,
        ),
    ],
    ids=["top-level", "a function called at top level"],
)
def test_an_unguarded_batch_is_refused_naming_the_line_and_the_fix(
    tmp_path: Path, body: str, line: int
) -> None:
    done = _run(tmp_path, BATCH + body)
    assert done.returncode == 1
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("robocram.batch.errors.UnguardedBatch: ")
    assert f"my_batch.py, line {line}:" in last
    assert 'if __name__ == "__main__":' in last
    assert "LOST" not in done.stdout  # no variant ran


def test_a_line_inside_the_main_guard_is_guarded_either_way_round(tmp_path: Path) -> None:
    script = tmp_path / "s.py"
    script.write_text(
        "import os\n"
        "if __name__ == '__main__':\n    run()\n"
        "if '__main__' == __name__:\n    run()\n"
        "if __name__ != '__main__':\n    run()\n",
        encoding="utf-8",
    )
    assert [_guarded(script, line) for line in (1, 3, 5, 7)] == [False, True, True, False]

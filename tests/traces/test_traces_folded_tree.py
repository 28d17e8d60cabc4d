"""A stored tree folds like a live one, and the trace keeps every failure's full text.

Issue 27, item 5: ``robocram runs show`` folds the tries a plan recovered from; with
``--verbose`` it prints them all, data included, as the trace stored them.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.cli import EXIT_OK, main
from robocram.execution import TopLevel, try_in_order
from robocram.execution.failures import NavigationPoseUnreachable
from robocram.traces import TraceDatabase, failures, trace_to

TARGET = "Pose(position=(-0.6898247307262457, -0.9550718645102443, 0.0))"


def _blocked() -> object:
    raise NavigationPoseUnreachable("pr2 would collide with ['kitchen']", target=TARGET)


@pytest.fixture
def recovered_run(tmp_path: Path) -> Path:
    db = tmp_path / "runs.db"
    with trace_to(db):
        TopLevel("deliver").run(
            lambda: try_in_order(("going", _blocked), ("going", _blocked), ("going", lambda: 1))
        )
    return db


def test_runs_show_folds_and_verbose_shows_the_stored_text(
    recovered_run: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["runs", "show", str(recovered_run)]) == EXIT_OK
    folded = capsys.readouterr().out.splitlines()
    assert (
        folded[3]
        == "    ├── ✗ going ×2: NavigationPoseUnreachable: pr2 would collide with ['kitchen']"
    )
    assert folded[4].startswith("    └── ✓ going#3 succeeded")
    assert main(["runs", "show", str(recovered_run), "--verbose"]) == EXIT_OK
    full = capsys.readouterr().out
    assert full.count(f"(target={TARGET!r})") == 2 and "going#2 failed" in full
    with TraceDatabase(recovered_run, create=False) as db:
        stored = failures(db)
    assert [f.message for f in stored] == [
        str(NavigationPoseUnreachable("pr2 would collide with ['kitchen']", target=TARGET))
    ] * 2

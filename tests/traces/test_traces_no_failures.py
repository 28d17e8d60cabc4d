"""``robocram runs failures`` says when there are none (issue 27, item 8).

Before, it printed nothing, which reads the same as a command that did not run.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.cli import EXIT_INPUT, EXIT_OK, main
from robocram.execution import TopLevel, seq
from robocram.traces import trace_to


@pytest.fixture
def clean_run(tmp_path: Path) -> Path:
    db = tmp_path / "runs.db"
    with trace_to(db):
        TopLevel("tidy").run(lambda: seq(("a", lambda: 1), ("b", lambda: 2)))
    return db


def test_no_failures_names_the_run_or_the_database(
    clean_run: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["runs", "failures", str(clean_run), "--run", "1"]) == EXIT_OK
    assert capsys.readouterr().out == "no failures in run 1\n"
    assert main(["runs", "failures", str(clean_run)]) == EXIT_OK
    assert capsys.readouterr().out == f"no failures in {clean_run}\n"
    assert main(["runs", "failures", str(clean_run), "--type", "TorsoGoalNotReached"]) == EXIT_OK
    assert capsys.readouterr().out == f"no failures of type TorsoGoalNotReached in {clean_run}\n"


def test_an_unknown_run_is_bad_input_not_no_failures(
    clean_run: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["runs", "failures", str(clean_run), "--run", "7"]) == EXIT_INPUT
    captured = capsys.readouterr()
    assert captured.out == "" and "7" in captured.err

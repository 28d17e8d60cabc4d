"""The ``robocram`` command line: runs list/show/failures, check-robot, exit codes."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from robocram.cli import EXIT_FAILED, EXIT_INPUT, EXIT_OK, EXIT_USAGE, main


def test_runs_list_show_and_failures(
    pick_up_trace: Any, capsys: pytest.CaptureFixture[str]
) -> None:
    db = str(pick_up_trace.db_path)
    assert main(["runs", "list", db]) == EXIT_OK
    lines = capsys.readouterr().out.splitlines()
    assert lines[1].split()[:3] == [str(pick_up_trace.run), "pick-mug", "succeeded"]
    assert main(["runs", "show", db, "--run", str(pick_up_trace.run)]) == EXIT_OK
    shown = capsys.readouterr().out
    assert "✗ too-high failed" in shown
    assert "ms: TorsoGoalNotReached from perform moving-torso" in shown
    assert "✓ perform gripping succeeded" in shown
    assert "motion moving-tcp" in shown and "n=3" in shown
    assert main(["runs", "failures", db, "--type", "TorsoGoalNotReached"]) == EXIT_OK
    out = capsys.readouterr().out.splitlines()
    assert out[0].split() == ["1", "TorsoGoalNotReached"]
    assert out[1].endswith("pick-mug/try_in_order/too-high/perform moving-torso")


def test_bad_input_exits_3_with_the_reason(
    tmp_path: Path, pick_up_trace: Any, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["runs", "show", str(pick_up_trace.db_path), "--run", "42"]) == EXIT_INPUT
    assert f"has no run 42; runs stored: {pick_up_trace.run}" in capsys.readouterr().err
    text = tmp_path / "readme.db"
    text.write_text("not a database " * 200)
    assert main(["runs", "list", str(text)]) == EXIT_INPUT
    assert "is not an SQLite trace database" in capsys.readouterr().err
    assert main(["runs", "list", str(tmp_path / "none.db")]) == EXIT_INPUT
    assert "no trace database at" in capsys.readouterr().err


def test_check_robot(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check-robot", "pr2"]) == EXIT_OK
    assert capsys.readouterr().out.startswith("pr2: ")
    urdf = tmp_path / "arm.urdf"
    urdf.write_text(
        '<robot name="arm"><link name="base"/><link name="tip"/>'
        '<joint name="j" type="revolute"><parent link="base"/><child link="tip"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        "</robot>"
    )
    assert main(["check-robot", str(urdf)]) == EXIT_OK
    assert capsys.readouterr().out.startswith("arm: 2 links, 1 joints (1 movable)")
    urdf.write_text(
        urdf.read_text().replace(
            '<link name="tip"/>',
            '<link name="tip"><visual><geometry><mesh filename="gone.stl"/></geometry>'
            "</visual></link>",
        )
    )
    assert main(["check-robot", str(urdf)]) == EXIT_FAILED
    assert "gone.stl" in capsys.readouterr().out
    urdf.write_text("<robot name='x'><joint name='j' type='fixed'/></robot>")
    assert main(["check-robot", str(urdf)]) == EXIT_INPUT
    assert main(["check-robot", str(tmp_path / "missing.urdf")]) == EXIT_INPUT
    assert "no URDF file at" in capsys.readouterr().err


def test_usage_errors_exit_2_and_help_lists_commands() -> None:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    cmd = [sys.executable, "-m", "robocram.cli"]
    usage = subprocess.run([*cmd, "runs"], env=env, capture_output=True, text=True)
    assert usage.returncode == EXIT_USAGE and "required: ACTION" in usage.stderr
    helped = subprocess.run([*cmd, "--help"], env=env, capture_output=True, text=True)
    assert helped.returncode == EXIT_OK
    for command in ("demo", "runs", "check-robot", "exit codes"):
        assert command in helped.stdout

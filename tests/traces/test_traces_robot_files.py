"""Runs of a robot described by a file are rebuilt from that file (issues 35 and 41).

A scene used to name its robots by description name alone, so the audit, the MCAP export
and the GIF of a run of a drafted robot failed with "no built-in robot". The trace now
keeps the file each robot was read from; a file moved since is given by hand, and a file
that now describes another URDF is refused rather than replayed wrongly.
"""

from __future__ import annotations

import json
import socket
import sqlite3
import subprocess
import sys
from contextlib import closing
from pathlib import Path

import pytest

from robocram.cli import main
from robocram.designators import a
from robocram.execution import perform
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.errors import RobotNotRebuilt
from robocram.traces.trajectory_audit import audit_runs

DATA = Path(__file__).resolve().parents[1] / "data"
FETCH = DATA / "fetch" / "fetch.py"
STRETCH = DATA / "stretch" / "stretch.py"
TORSO = 0.2  # [m] the Fetch's torso lift the run raises it to


@pytest.fixture(scope="module")
def fetch_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    db_path = tmp_path_factory.mktemp("fetch") / "runs.db"
    scene = tabletop_scene(str(FETCH))
    robot = scene.world.robots()[0].name
    with trace_to(db_path, world=scene.world), simulated_robot(scene.world, robot):
        perform(a.motion(type="moving-torso", joint_angle=TORSO))
    scene.world.close()
    return db_path


def _stored_source(db_path: Path) -> str:
    with sqlite3.connect(db_path) as db:
        (scene,) = db.execute("SELECT scene FROM runs").fetchone()
    return next(r["source"] for r in json.loads(scene) if "robot" in r)


def _move_source(db_path: Path, tmp_path: Path, to: str) -> Path:
    """A copy of the store whose robot was read from ``to`` (a file moved or changed)."""
    copy = tmp_path / "moved.db"
    copy.write_bytes(db_path.read_bytes())
    with closing(sqlite3.connect(copy)) as db:  # closed: the write leaves the WAL
        (scene,) = db.execute("SELECT scene FROM runs").fetchone()
        recipes = json.loads(scene)
        for recipe in recipes:
            if "robot" in recipe:
                recipe["source"] = to
        db.execute("UPDATE runs SET scene = ?", (json.dumps(recipes),))
        db.commit()
    return copy


def test_the_trace_keeps_the_file_and_the_audit_rebuilds_the_robot(fetch_run: Path) -> None:
    assert _stored_source(fetch_run) == f"{FETCH.resolve()}:description"
    with TraceDatabase(fetch_run, create=False) as db:
        report = audit_runs(db)
    assert report.clean, report.summary_lines()
    assert report.trajectories == 1 and report.configurations > 10  # the torso's, replayed


def test_a_moved_file_is_named_with_the_fix_and_can_be_given(
    fetch_run: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A trace of an older robocram keeps no copy: its moved file is asked for."""
    moved = _move_source(fetch_run, tmp_path, str(tmp_path / "gone.py") + ":description")
    older = _drop_copies(moved, tmp_path)
    with TraceDatabase(older, create=False) as db, pytest.raises(RobotNotRebuilt) as err:
        audit_runs(db)
    assert "gone.py" in str(err.value) and "--robot-file" in str(err.value)
    assert main(["runs", "audit", str(older)]) == 3  # bad input: one line, no traceback
    assert "gone.py" in capsys.readouterr().err
    assert main(["runs", "audit", str(older), "--robot-file", str(FETCH)]) == 0
    out = tmp_path / "run.mcap"
    assert main(["runs", "export", str(older), "--mcap", str(out), "--robot-file", str(FETCH)]) == 0
    assert out.stat().st_size > 10_000


def test_a_file_given_that_describes_another_urdf_is_refused(fetch_run: Path) -> None:
    with TraceDatabase(fetch_run, create=False) as db, pytest.raises(RobotNotRebuilt) as err:
        audit_runs(db, robots={"fetch": f"{STRETCH}:description"})
    assert "another URDF" in str(err.value)


def test_a_file_changed_since_gives_way_to_the_traces_copy(fetch_run: Path, tmp_path: Path) -> None:
    changed = _move_source(fetch_run, tmp_path, f"{STRETCH}:description")
    with TraceDatabase(changed, create=False) as db:
        report = audit_runs(db)
    assert report.clean, report.summary_lines()
    assert report.trajectories == 1 and report.configurations > 10


def _drop_copies(db_path: Path, tmp_path: Path) -> Path:
    """A copy of the store as an older robocram wrote it: no copy of the description."""
    older = tmp_path / "older.db"
    older.write_bytes(db_path.read_bytes())
    with closing(sqlite3.connect(older)) as db:  # closed: the write leaves the WAL
        db.execute("DELETE FROM robot_descriptions")
        db.commit()
    return older


def test_the_trace_keeps_a_copy_of_the_description(fetch_run: Path) -> None:
    with sqlite3.connect(fetch_run) as db:
        rows = db.execute("SELECT name, description FROM robot_descriptions").fetchall()
    assert [name for name, _ in rows] == ["fetch"]
    stored = json.loads(rows[0][1])
    assert stored["torso_joint"] == "torso_lift_joint" and "arm" in stored["arms"]


def test_a_moved_file_is_audited_exported_and_replayed_from_the_traces_copy(
    fetch_run: Path, tmp_path: Path
) -> None:
    moved = _move_source(fetch_run, tmp_path, str(tmp_path / "gone.py") + ":description")
    out = tmp_path / "run.mcap"
    with socket.socket() as probe:  # a free port for the replay's viewer
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    code = (
        "import sys; from robocram.cli import main; "
        f"sys.exit(main(['runs', 'audit', {str(moved)!r}]) or "
        f"main(['runs', 'export', {str(moved)!r}, '--mcap', {str(out)!r}]) or "
        f"main(['replay', {str(moved)!r}, '--port', '{port}', '--seconds', '0.2']))"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "0 findings" in done.stdout or "clean" in done.stdout, done.stdout[-2000:]
    assert out.stat().st_size > 10_000
    assert f"run 1 at http://127.0.0.1:{port}" in done.stdout  # the replay built its world

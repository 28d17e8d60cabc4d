"""Stored trajectory rows are checked on read: a damaged row is a typed error naming the
run and the trajectory; exports leave no stub; replays skip it and say so (issue 42)."""

from __future__ import annotations

import shutil
import sqlite3
import struct
from pathlib import Path
from typing import Any

import pytest

from robocram.traces import (
    DamagedTrajectory,
    DamagedTrajectoryWarning,
    TraceDatabase,
    build_scene,
    export_mcap,
    replay_frames,
    run_trajectories,
)
from robocram.traces.queries import require_run

NAN = struct.pack("<d", float("nan"))
DAMAGES = {  # column, SQL expression of the damaged value, what the error says
    "truncated": ("positions", "substr(positions, 1, length(positions) - 3)", "cut short"),
    "nan": ("times", "?", "not finite"),
    "json": ("joint_names", "'[\"a\", '", "Expecting"),
    "backwards": ("times", "?", "run backwards"),
    "short": ("positions", "substr(positions, 1, 8)", "hold 1 numbers"),
}


def _damaged(trajectory_run: Any, tmp_path: Path, damage: str) -> tuple[Path, int, int]:
    """A copy of the traced run with its second trajectory's row damaged."""
    db_path = tmp_path / "runs.db"
    shutil.copy(trajectory_run.db_path, db_path)
    column, value, _ = DAMAGES[damage]
    with sqlite3.connect(db_path) as conn:
        rid, seq, times = conn.execute(
            "SELECT id, sequence, times FROM trajectories WHERE run_id = ? ORDER BY sequence",
            (trajectory_run.run,),
        ).fetchall()[1]
        count = len(times) // 8
        blob = NAN * count if damage == "nan" else struct.pack(f"<{count}d", *range(count, 0, -1))
        params = (blob, rid) if value == "?" else (rid,)
        conn.execute(f"UPDATE trajectories SET {column} = {value} WHERE id = ?", params)
    return db_path, trajectory_run.run, seq


@pytest.mark.parametrize("damage", sorted(DAMAGES))
def test_a_damaged_row_names_the_run_and_the_trajectory(
    trajectory_run: Any, tmp_path: Path, damage: str
) -> None:
    db_path, run, seq = _damaged(trajectory_run, tmp_path, damage)
    with pytest.raises(DamagedTrajectory) as caught:
        run_trajectories(db_path, run)
    assert (caught.value.run, caught.value.trajectory) == (run, seq)
    assert f"run {run}, trajectory {seq}" in str(caught.value)
    assert DAMAGES[damage][2] in str(caught.value)


def test_an_export_of_a_damaged_run_leaves_no_file(trajectory_run: Any, tmp_path: Path) -> None:
    db_path, run, seq = _damaged(trajectory_run, tmp_path, "truncated")
    out = tmp_path / "run.mcap"
    with TraceDatabase(db_path, create=False) as db, pytest.raises(DamagedTrajectory):
        export_mcap(db, run, out)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["runs.db"]


def test_a_replay_skips_the_damaged_row_and_says_so(trajectory_run: Any, tmp_path: Path) -> None:
    db_path, run, seq = _damaged(trajectory_run, tmp_path, "nan")
    whole = len(run_trajectories(trajectory_run.db_path, run))
    with TraceDatabase(db_path, create=False) as db:
        with pytest.warns(DamagedTrajectoryWarning, match=rf"run {run}, trajectory {seq}"):
            kept = run_trajectories(db, run, skip_damaged=True)
        assert [t.index for t in kept] == [i for i in range(whole) if i != seq]
        scene = require_run(db, run).scene
        assert scene is not None
        with build_scene(scene) as world, pytest.warns(DamagedTrajectoryWarning):
            frames = list(replay_frames(db, run, world, period=0.2))
    assert len(frames) > whole

"""The trace store: a traced pick-up reads back as the same tree, failures and durations."""

from __future__ import annotations

import sqlite3
from pathlib import Path
from typing import Any

import pytest

from robocram.execution import TaskStatus, run_top_level
from robocram.traces import (
    SCHEMA_VERSION,
    NotATraceDatabase,
    SchemaVersionMismatch,
    TraceDatabase,
    UnknownRun,
    designator_properties,
    durations,
    failure_counts,
    failures,
    runs,
    task_tree,
    trace_to,
)


def test_stored_tree_equals_the_live_tree(pick_up_trace: Any) -> None:
    with TraceDatabase(pick_up_trace.db_path, create=False) as db:
        stored = task_tree(db, pick_up_trace.run)
    assert stored == pick_up_trace.tree
    names = [t.name for t in stored.children[0].children]
    assert names == ["too-high", "pick"]
    motions = [t.name for t in stored.children[0].children[1].walk() if t.name.startswith("perf")]
    assert motions[:3] == [
        "perform moving-arm-joints",
        "perform moving-arm-joints#2",
        "perform looking",
    ]
    assert motions[-2:] == ["perform gripping", "perform moving-tcp#3"]
    assert stored.status is TaskStatus.SUCCEEDED


def test_failing_branch_is_stored_with_its_type(pick_up_trace: Any) -> None:
    with TraceDatabase(pick_up_trace.db_path, create=False) as db:
        found = failures(db, "TorsoGoalNotReached")
        assert failure_counts(db) == {"TorsoGoalNotReached": 1}
        (summary,) = runs(db)
    (failure,) = found
    assert failure.path == "pick-mug/try_in_order/too-high/perform moving-torso"
    assert "outside" in failure.message and failure.run == pick_up_trace.run
    assert summary.status == "succeeded" and summary.failed_tasks == 2  # perform + branch
    assert summary.tasks == len(list(pick_up_trace.tree.walk()))


def test_designators_and_durations_per_motion(pick_up_trace: Any) -> None:
    with TraceDatabase(pick_up_trace.db_path, create=False) as db:
        stats = durations(db)
        props = designator_properties(
            db, pick_up_trace.run, "pick-mug/try_in_order/too-high/perform moving-torso"
        )
    assert props == [("type", "moving-torso"), ("joint_angle", 5.0)]
    assert stats["motion moving-tcp"].count == 3
    live = [
        t.duration for t in pick_up_trace.tree.walk() if t.name.startswith("perform moving-tcp")
    ]
    assert stats["motion moving-tcp"].total == pytest.approx(sum(live), abs=1e-9)


def test_not_sqlite_is_a_typed_error(tmp_path: Path) -> None:
    path = tmp_path / "notes.db"
    path.write_text("these are notes, not a database\n" * 100)
    with pytest.raises(NotATraceDatabase, match="notes.db is not an SQLite trace database"):
        TraceDatabase(path)


def test_other_schema_version_is_a_typed_error(tmp_path: Path) -> None:
    path = tmp_path / "old.db"
    TraceDatabase(path).close()
    with sqlite3.connect(path) as con:
        con.execute("UPDATE schema_info SET version = ?", (SCHEMA_VERSION + 7,))
    with pytest.raises(SchemaVersionMismatch, match=f"schema version {SCHEMA_VERSION + 7}"):
        TraceDatabase(path)
    other = tmp_path / "other.db"
    with sqlite3.connect(other) as con:
        con.execute("CREATE TABLE notes (text)")
    with pytest.raises(SchemaVersionMismatch, match="no robocram trace schema"):
        TraceDatabase(other)


def test_unknown_run_lists_the_runs(tmp_path: Path) -> None:
    path = tmp_path / "runs.db"
    with trace_to(path):
        run_top_level(lambda: 1, name="one")
        run_top_level(lambda: 2, name="two")
    with TraceDatabase(path) as db, pytest.raises(UnknownRun, match="runs stored: 1, 2") as err:
        task_tree(db, 9)
    assert err.value.known == [1, 2]


def test_missing_database_is_not_created_when_reading(tmp_path: Path) -> None:
    with pytest.raises(Exception, match="no trace database"):
        TraceDatabase(tmp_path / "absent.db", create=False)
    assert not (tmp_path / "absent.db").exists()

"""Opening a trace: other files are never changed, and every refusal is typed (issue 24).

Before: opening another application's SQLite file switched it to WAL for good (even with
``create=False``), each refusal was retried for 3.5 s, a damaged trace failed later with
SQL text, read-only media and a full disk were "not an SQLite trace database", and a path
below a file raised ``FileExistsError``.
"""

from __future__ import annotations

import hashlib
import sqlite3
from pathlib import Path

import pytest
from sqlalchemy import event

from robocram.traces import (
    DamagedTrace,
    NotATraceDatabase,
    SchemaVersionMismatch,
    TraceDatabase,
    TraceLocked,
    TraceStorageError,
)
from robocram.traces import database as database_module
from robocram.traces.trace_probe import sqlite_error


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _other_application_file(path: Path) -> Path:
    with sqlite3.connect(path) as con:
        con.execute("CREATE TABLE notes (text TEXT)")
        con.execute("INSERT INTO notes VALUES ('buy milk')")
    con.close()
    return path


@pytest.mark.parametrize("create", [False, True])
def test_another_applications_sqlite_file_is_left_exactly_as_it_was(
    tmp_path: Path, create: bool
) -> None:
    other = _other_application_file(tmp_path / "notes.sqlite")
    before = _digest(other)
    with pytest.raises(SchemaVersionMismatch, match="no robocram trace schema"):
        TraceDatabase(other, create=create)
    assert _digest(other) == before
    with sqlite3.connect(other) as con:
        assert con.execute("PRAGMA journal_mode").fetchone() == ("delete",)
    con.close()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.sqlite"]


def test_a_refusal_is_not_retried(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    pauses: list[float] = []
    monkeypatch.setattr(database_module.time, "sleep", pauses.append)
    notes = tmp_path / "notes.db"
    notes.write_text("these are notes, not a database\n" * 100)
    with pytest.raises(NotATraceDatabase, match="does not start with SQLite's header"):
        TraceDatabase(notes)
    with pytest.raises(SchemaVersionMismatch):
        TraceDatabase(_other_application_file(tmp_path / "other.db"))
    assert pauses == []


def test_an_empty_file_gets_the_schema(tmp_path: Path) -> None:
    empty = tmp_path / "empty.db"
    empty.touch()
    TraceDatabase(empty).close()
    with sqlite3.connect(empty) as con:
        assert con.execute("SELECT version FROM schema_info").fetchone() == (
            database_module.SCHEMA_VERSION,
        )
    con.close()


def test_a_trace_with_its_tasks_table_missing_is_a_damaged_trace(tmp_path: Path) -> None:
    path = tmp_path / "runs.db"
    TraceDatabase(path).close()
    with sqlite3.connect(path) as con:
        con.execute("DROP TABLE tasks")
    con.close()
    with pytest.raises(
        DamagedTrace, match=r"table\(s\) tasks are missing; .* into a new file"
    ) as err:
        TraceDatabase(path, create=False)
    assert err.value.missing == ["tasks"]


def test_a_trace_path_below_a_file_names_that_file(tmp_path: Path) -> None:
    (tmp_path / "notes.txt").write_text("notes")
    with pytest.raises(TraceStorageError, match=r"notes.txt is a file, not a folder") as err:
        TraceDatabase(tmp_path / "notes.txt" / "runs" / "runs.db")
    assert err.value.kind == "path"


def test_read_only_storage_is_told_apart_from_not_a_trace(tmp_path: Path) -> None:
    path = tmp_path / "runs.db"
    TraceDatabase(path).close()
    con = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    with pytest.raises(sqlite3.OperationalError) as raised:
        con.execute("CREATE TABLE more (x)")
    con.close()
    error = sqlite_error(path, raised.value)
    assert isinstance(error, TraceStorageError) and error.kind == "read-only"
    assert "copy it to a writable folder" in str(error)


def test_a_full_disk_is_told_apart_from_not_a_trace(tmp_path: Path) -> None:
    con = sqlite3.connect(tmp_path / "small.db")
    con.execute("PRAGMA max_page_count = 2")  # SQLite's own "disk is full" at two pages
    with pytest.raises(sqlite3.OperationalError) as raised:
        con.execute("CREATE TABLE big (x)")
        con.execute("INSERT INTO big VALUES (zeroblob(100000))")
    con.close()
    error = sqlite_error(tmp_path / "small.db", raised.value)
    assert isinstance(error, TraceStorageError) and error.kind == "disk full"
    assert "free some space" in str(error)


def test_a_damaged_file_is_still_not_a_trace(tmp_path: Path) -> None:
    path = tmp_path / "cut.db"
    TraceDatabase(path).close()
    path.write_bytes(path.read_bytes()[:100] + b"\xff" * 4000)
    with pytest.raises(NotATraceDatabase):
        TraceDatabase(path, create=False)


def test_locked_is_retried_and_only_locked(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    pauses: list[float] = []
    monkeypatch.setattr(database_module.time, "sleep", pauses.append)
    answers: list[Exception | str] = [TraceLocked(tmp_path), TraceLocked(tmp_path), "opened"]

    def attempt() -> str:
        answer = answers.pop(0)
        if isinstance(answer, Exception):
            raise answer
        return answer

    assert database_module.retry_while_locked(attempt) == "opened"
    assert pauses == [database_module.OPEN_RETRY_PAUSE] * 2

    def damaged() -> str:
        raise DamagedTrace(tmp_path, ["tasks"])

    with pytest.raises(DamagedTrace):
        database_module.retry_while_locked(damaged)
    assert len(pauses) == 2


def _page_limit(pages: int) -> object:
    """A connect hook that caps the file at ``pages`` SQLite pages: a disk that fills."""

    def hook(connection: sqlite3.Connection, _record: object) -> None:
        connection.execute(f"PRAGMA max_page_count = {pages}")

    return hook


def test_a_disk_that_fills_while_appending_is_named_and_what_fit_is_kept(tmp_path: Path) -> None:
    path = tmp_path / "runs.db"
    db = TraceDatabase(path)
    with db.write() as session:
        session.connection().exec_driver_sql("CREATE TABLE filler (data BLOB)")
    event.listen(db.engine, "connect", _page_limit(40))
    db.engine.dispose()  # the next connections fill up at 40 pages
    written = 0
    with pytest.raises(TraceStorageError) as info:
        for _ in range(1000):
            with db.write() as session:
                session.connection().exec_driver_sql("INSERT INTO filler VALUES (zeroblob(8000))")
            written += 1
    assert info.value.kind == "disk full" and "free some space" in str(info.value)
    assert 0 < written < 1000
    db.close()
    with TraceDatabase(path, create=False) as again, again.read() as session:
        rows = session.connection().exec_driver_sql("SELECT COUNT(*) FROM filler").scalar()
    assert rows == written  # every transaction that committed is there


def test_a_trace_the_disk_cannot_hold_is_named_and_no_empty_file_is_left(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(database_module, "_configure_connection", _page_limit(1))
    path = tmp_path / "runs.db"
    with pytest.raises(TraceStorageError) as info:
        TraceDatabase(path)
    assert info.value.kind == "disk full"
    assert sorted(p.name for p in tmp_path.iterdir()) == []

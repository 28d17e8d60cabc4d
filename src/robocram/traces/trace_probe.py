"""Looking at a trace file before opening it for writing: read-only, and typed answers.

Opening an SQLite file for writing switches it to WAL for good, so a file that is not a
robocram trace is never opened that way: :func:`probe_trace` reads it read-only first,
and the schema is created only in a new or empty file. SQLite's errors are sorted into
the storage's problems (read-only, full, locked) and the file's (not a trace).
"""

from __future__ import annotations

import errno
import shutil
import sqlite3
from pathlib import Path
from urllib.parse import quote

from robocram.traces.errors import (
    DamagedTrace,
    NotATraceDatabase,
    SchemaVersionMismatch,
    TraceError,
    TraceLocked,
    TraceStorageError,
)
from robocram.traces.schema import ADDED_TABLES, SCHEMA_VERSION, Base, upgradable

SQLITE_HEADER = b"SQLite format 3\x00"
_READ_ONLY = "the file or its folder is read-only (read-only media or permissions)"
_FULL = "the disk is full"
FULL_BELOW = 1 << 20  # [bytes] a file system with less free than this counts as full


def probe_trace(path: Path) -> bool:
    """Whether ``path`` is new or empty (the schema may be made), reading it only.

    Raises:
        NotATraceDatabase: the file is not SQLite.
        SchemaVersionMismatch: SQLite, but another application's or version's file.
        DamagedTrace: a robocram trace with tables missing.
        TraceStorageError: the path cannot hold a file (a file where a folder should be).
    """
    check_folder(path)
    if not path.exists():
        return True
    if path.is_dir():
        raise TraceStorageError(path, "path", "it is a folder", "give a file name inside it")
    try:
        with path.open("rb") as file:
            header = file.read(len(SQLITE_HEADER))
    except OSError as err:
        raise storage_error(path, err) from err
    if not header:
        return True
    if header != SQLITE_HEADER:
        raise NotATraceDatabase(path, "the file does not start with SQLite's header")
    tables, version = _read_only_look(path)
    if not tables:
        return True
    if version is None:
        raise SchemaVersionMismatch(path, None, SCHEMA_VERSION)
    if version != SCHEMA_VERSION and not upgradable(version):
        raise SchemaVersionMismatch(path, version, SCHEMA_VERSION)
    added_later = {t for v, names in ADDED_TABLES.items() if v > version for t in names}
    missing = set(Base.metadata.tables) - added_later - tables
    if missing:
        raise DamagedTrace(path, sorted(missing))
    return False


def check_folder(path: Path) -> None:
    """Refuse a path below a file (``notes.txt/runs.db``), naming that file."""
    for ancestor in path.parents:
        if ancestor.exists():
            if not ancestor.is_dir():
                raise TraceStorageError(
                    path, "path", f"{ancestor} is a file, not a folder", "choose a path in a folder"
                )
            return


def _read_only_look(path: Path) -> tuple[set[str], int | None]:
    """The file's tables and its schema version (``None``: no ``schema_info``)."""
    try:
        con = sqlite3.connect(f"file:{quote(str(path.resolve()))}?mode=ro", uri=True)
        try:
            rows = con.execute("SELECT name FROM sqlite_master WHERE type = 'table'")
            tables = {str(name) for (name,) in rows}
            if "schema_info" not in tables:
                return tables, None
            row = con.execute("SELECT version FROM schema_info").fetchone()
        finally:
            con.close()
    except sqlite3.DatabaseError as err:
        raise sqlite_error(path, err) from err
    return tables, None if row is None else int(row[0])


def storage_problem(path: Path, err: Exception) -> TraceError | None:
    """The typed error of an SQLite error that is the storage's (locked, read-only, full),
    or None: the error is not about where the file lies."""
    text = str(err).lower()
    if "locked" in text or "busy" in text:
        return TraceLocked(path)
    if "readonly" in text or "read-only" in text:
        return TraceStorageError(path, "read-only", _READ_ONLY, "copy it to a writable folder")
    if (
        "disk is full" in text
        or "disk full" in text
        or (
            "disk i/o error" in text
            and _nearly_full(path)  # SQLite's word when the WAL cannot grow
        )
    ):
        return TraceStorageError(path, "disk full", _FULL, "free some space or write elsewhere")
    if "disk i/o error" in text:
        return TraceStorageError(
            path,
            "I/O error",
            "the storage failed to read or write",
            "check the disk, or write elsewhere",
        )
    return None


def _nearly_full(path: Path) -> bool:
    """Whether the file system holding ``path`` has less than :data:`FULL_BELOW` free."""
    folder = next((p for p in (path, *path.parents) if p.exists()), Path("."))
    try:
        return shutil.disk_usage(folder).free < FULL_BELOW
    except OSError:
        return False


def sqlite_error(path: Path, err: Exception) -> TraceError:
    """The typed error of an SQLite error on ``path``: storage problems apart from the file's."""
    storage = storage_problem(path, err)
    if storage is not None:
        return storage
    text = str(err).lower()
    if "unable to open" in text:
        return TraceStorageError(
            path,
            "read-only",
            f"SQLite cannot open it ({err}); {_READ_ONLY}?",
            "check the folder is writable, or copy the file to one that is",
        )
    return NotATraceDatabase(path, str(err))


def storage_error(path: Path, err: OSError) -> TraceError:
    """The typed error of an ``OSError`` while reading ``path`` or making its folder."""
    if err.errno in (errno.EROFS, errno.EACCES, errno.EPERM):
        return TraceStorageError(
            path, "read-only", f"{_READ_ONLY} ({err.strerror})", "copy it to a writable folder"
        )
    if err.errno in (errno.ENOSPC, errno.EDQUOT):
        return TraceStorageError(path, "disk full", _FULL, "free some space or write elsewhere")
    return TraceStorageError(path, "path", str(err.strerror or err), "choose another path")

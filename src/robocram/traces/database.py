"""Opening a trace database: SQLite in WAL mode, one writer at a time, schema checked.

WAL lets readers (a viewer, ``robocram runs``) read while a plan writes, and lets several
processes append runs to one file: each write transaction starts with ``BEGIN IMMEDIATE``,
so writers queue on SQLite's lock (``busy_timeout``) instead of failing half-way.
Within a process one lock serialises the writers of all threads. A file of an older
version whose successors only added tables is upgraded in place on opening. A file that
is not a robocram trace is never written: it is probed read-only first
(``traces/trace_probe.py``), and only a new or empty file gets the schema.
"""

from __future__ import annotations

import sqlite3
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any, TypeVar

from sqlalchemy import Connection, create_engine, event, inspect, select, update
from sqlalchemy.exc import DatabaseError, OperationalError
from sqlalchemy.orm import Session

from robocram.traces.errors import SchemaVersionMismatch, TraceError, TraceLocked
from robocram.traces.schema import (
    ADDED_COLUMNS,
    ADDED_TABLES,
    SCHEMA_VERSION,
    Base,
    SchemaInfo,
    upgradable,
)
from robocram.traces.trace_probe import probe_trace, sqlite_error, storage_error, storage_problem

BUSY_TIMEOUT = 60_000  # [ms] a writer waits this long for another process's transaction
_WRITE = "robocram_write"
OPEN_RETRIES = 50  # tries to open a file another process is setting up
OPEN_RETRY_PAUSE = 0.05  # [s] between them
T = TypeVar("T")


class TraceDatabase:
    """An open trace database file; thread-safe; ``close()`` it (or use ``with``)."""

    def __init__(self, path: str | Path, create: bool = True) -> None:
        self.path = Path(path)
        existed = self.path.exists()
        if not create and not existed:
            raise TraceError(f"no trace database at {self.path}; record one with trace_to(path)")
        fresh = retry_while_locked(lambda: probe_trace(self.path))
        if fresh and not create:
            raise SchemaVersionMismatch(self.path, None, SCHEMA_VERSION)
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as err:
            raise storage_error(self.path, err) from err
        self.engine = create_engine(f"sqlite:///{self.path}")
        event.listen(self.engine, "connect", _configure_connection)
        event.listen(self.engine, "begin", _begin)
        self._writer = self.engine.execution_options(**{_WRITE: True})
        self._lock = threading.Lock()
        self._connection: Connection | None = None
        try:
            self._open_schema(fresh)
        except BaseException:
            self.engine.dispose()
            if not existed:  # a file this call made and could not fill: none is left behind
                for made in (
                    self.path,
                    *(self.path.with_name(self.path.name + x) for x in ("-wal", "-shm")),
                ):
                    made.unlink(missing_ok=True)
            raise

    def _open_schema(self, create: bool) -> None:
        """Check (or create) the schema, retrying while another process sets the file up.

        Two batch workers opening a new file at once race to switch it to WAL and create
        the tables; SQLite answers the loser "locked" at once, without waiting out
        ``busy_timeout``. Only "locked" or "busy" is retried; the retries are bounded, and
        the answer never depends on them.
        """

        def check() -> None:
            try:
                self._check_schema(create)
            except TraceLocked:
                self.engine.dispose()  # the next connection sets its pragmas again
                raise

        retry_while_locked(check)

    def _check_schema(self, create: bool) -> None:
        try:
            with self.write() as session:
                tables = set(inspect(session.connection()).get_table_names())
                if not tables and create:
                    Base.metadata.create_all(session.connection())
                    session.add(SchemaInfo(version=SCHEMA_VERSION))
                    return
                version = (
                    session.scalar(select(SchemaInfo.version)) if "schema_info" in tables else None
                )
                if version is not None and upgradable(version):
                    _add_tables(session, version)
                    version = SCHEMA_VERSION
        except DatabaseError as err:
            raise sqlite_error(self.path, err.orig or err) from err
        if version != SCHEMA_VERSION:
            raise SchemaVersionMismatch(self.path, version, SCHEMA_VERSION)

    @contextmanager
    def write(self) -> Iterator[Session]:
        """One write transaction (committed on leaving, rolled back on an error).

        Raises:
            TraceStorageError: the disk is full, or the file became read-only.
            TraceLocked: another process holds the file longer than SQLite waits.
        """
        with (
            self._storage_errors(),
            self._lock,
            Session(self._writer, expire_on_commit=False) as session,
            session.begin(),
        ):
            yield session

    @contextmanager
    def append(self) -> Iterator[Connection]:
        """One write transaction on the writer's own long-lived connection (fast, Core);
        storage errors as :meth:`write` raises them."""
        with self._storage_errors(), self._lock:
            if self._connection is None:
                self._connection = self._writer.connect()
            with self._connection.begin():
                yield self._connection

    @contextmanager
    def _storage_errors(self) -> Iterator[None]:
        """SQLite's storage errors while writing as typed errors naming the file and the
        fix (a full disk said "not an SQLite trace database", issue 42); others as raised."""
        try:
            yield
        except OperationalError as err:
            typed = storage_problem(self.path, err.orig or err)
            if typed is None:
                raise
            raise typed from err

    @contextmanager
    def read(self) -> Iterator[Session]:
        """A read-only session seeing one consistent snapshot of the file."""
        with Session(self.engine, expire_on_commit=False) as session, session.begin():
            yield session

    def close(self) -> None:
        """Release the file's connections."""
        with self._lock:
            if self._connection is not None:
                self._connection.close()
                self._connection = None
        self.engine.dispose()

    def __enter__(self) -> TraceDatabase:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __repr__(self) -> str:
        return f"TraceDatabase({str(self.path)!r})"


def retry_while_locked(attempt: Callable[[], T]) -> T:
    """``attempt()``, tried again while the file is locked or busy (and only then)."""
    for _ in range(OPEN_RETRIES - 1):
        try:
            return attempt()
        except TraceLocked:
            time.sleep(OPEN_RETRY_PAUSE)
    return attempt()


def _add_tables(session: Session, version: int) -> None:
    """Upgrade a file of ``version`` in place: add the tables and nullable columns added
    since (a table created here already has its later columns), set the version."""
    connection = session.connection()
    for later in range(version + 1, SCHEMA_VERSION + 1):
        for name in ADDED_TABLES.get(later, ()):
            Base.metadata.tables[name].create(connection, checkfirst=True)
        for name, column in ADDED_COLUMNS.get(later, ()):
            present = {c["name"] for c in inspect(connection).get_columns(name)}
            if column not in present:
                kind = Base.metadata.tables[name].columns[column].type.compile(connection.dialect)
                connection.exec_driver_sql(f'ALTER TABLE {name} ADD COLUMN "{column}" {kind}')
    session.execute(update(SchemaInfo).values(version=SCHEMA_VERSION))


def _configure_connection(dbapi_connection: sqlite3.Connection, _record: Any) -> None:
    dbapi_connection.isolation_level = None  # transactions are begun in _begin, explicitly
    cursor = dbapi_connection.cursor()
    cursor.execute(f"PRAGMA busy_timeout = {BUSY_TIMEOUT}")
    cursor.execute("PRAGMA journal_mode = WAL")
    cursor.execute("PRAGMA synchronous = NORMAL")  # WAL + NORMAL: commits survive a crash
    cursor.execute("PRAGMA foreign_keys = ON")
    cursor.close()


def _begin(connection: Any) -> None:
    writing = connection.get_execution_options().get(_WRITE, False)
    connection.exec_driver_sql("BEGIN IMMEDIATE" if writing else "BEGIN")

"""Errors of the trace store: one root, each naming the culprit and the fix."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path


class TraceError(Exception):
    """Root of every trace-store error."""


class NotATraceDatabase(TraceError):  # noqa: N818 - reads as what the file is
    """The file exists but is not an SQLite database (or is damaged)."""

    def __init__(self, path: Path, reason: str) -> None:
        super().__init__(
            f"{path} is not an SQLite trace database ({reason}); pass a file written by "
            "trace_to(...) or a new path to create one"
        )
        self.path = path


class SchemaVersionMismatch(TraceError):  # noqa: N818
    """The database was written with another trace schema version."""

    def __init__(self, path: Path, found: int | None, expected: int) -> None:
        what = "no robocram trace schema" if found is None else f"schema version {found}"
        super().__init__(
            f"{path} has {what}, this robocram reads version {expected}; "
            "record the run again with this version or use a new database file"
        )
        self.path, self.found, self.expected = path, found, expected


class UnknownRun(TraceError):  # noqa: N818
    """A run id that the database does not hold."""

    def __init__(self, path: Path, run: int, known: Sequence[int]) -> None:
        shown = ", ".join(map(str, known[:20])) + (" ..." if len(known) > 20 else "")
        super().__init__(
            f"{path} has no run {run}; runs stored: {shown or 'none'} "
            "(list them with `robocram runs list DB`)"
        )
        self.path, self.run, self.known = path, run, list(known)


class NoWorldState(TraceError):  # noqa: N818
    """A run with no world state stored at or before the time asked for."""

    def __init__(self, run: int, time: float) -> None:
        super().__init__(
            f"run {run} has no world state at or before t={time:.6f} s; trace with "
            "trace_to(db, world=world) to store world states at motion boundaries"
        )
        self.run, self.time = run, time


class NoSceneStored(TraceError):  # noqa: N818 - reads as what is missing
    """A run traced without its world: nothing to rebuild it from for a replay or an audit."""

    def __init__(self, run: int) -> None:
        super().__init__(
            f"run {run} stores no scene, so its world cannot be rebuilt; trace it with "
            "trace_to(db, world=world)"
        )
        self.run = run


class DamagedTrace(TraceError):  # noqa: N818 - reads as what the file is
    """A robocram trace with tables missing (changed outside robocram, or cut short)."""

    def __init__(self, path: Path, missing: Sequence[str]) -> None:
        super().__init__(
            f"{path} is a damaged robocram trace: table(s) {', '.join(sorted(missing))} are "
            "missing; it was changed outside robocram: record the runs again into a new file"
        )
        self.path, self.missing = path, sorted(missing)


class TraceStorageError(TraceError):
    """The storage, not the file, is the problem: read-only, full, or no folder to write in.

    ``kind`` is ``"read-only"``, ``"disk full"``, ``"I/O error"`` or ``"path"``.
    """

    def __init__(self, path: Path, kind: str, problem: str, fix: str) -> None:
        super().__init__(f"cannot use trace {path}: {problem}; {fix}")
        self.path, self.kind, self.problem = path, kind, problem


class TraceLocked(TraceError):  # noqa: N818
    """Another process kept the file locked past the waiting time."""

    def __init__(self, path: Path) -> None:
        super().__init__(
            f"{path} stayed locked by another writer; wait for it to finish or use another file"
        )
        self.path = path


class MissingRobotDescription(UserWarning):  # noqa: N818 - reads as what is missing
    """A run's trace holds no URDF of its robot: it was written before robocram stored them."""

    def __init__(self, run: int, robot_name: str) -> None:
        super().__init__(
            f"run {run}'s trace stores no URDF of robot {robot_name!r} (written by an older "
            "robocram): the MCAP file has no /robot_description, so Foxglove draws no robot; "
            "trace the run again to get it"
        )
        self.run, self.robot = run, robot_name


class RobotNotRebuilt(TraceError):  # noqa: N818 - reads as what went wrong
    """A traced robot cannot be built again as it ran: its description file is gone, does
    not load, or describes another URDF now."""

    def __init__(self, robot_name: str, source: str, problem: str) -> None:
        super().__init__(
            f"robot {robot_name!r} of this trace was described by {source}, which {problem}; "
            f"give the file it ran with (--robot-file FILE.py, or robots={{{robot_name!r}: "
            "'FILE.py'}} in code)"
        )
        self.robot, self.source, self.problem = robot_name, source, problem


class DamagedTrajectory(TraceError):  # noqa: N818 - reads as what the row is
    """A stored trajectory row that does not decode to a trajectory: bad JSON, a truncated
    blob, numbers that are not finite, times running backwards."""

    def __init__(self, run: int, trajectory: int, reason: str) -> None:
        super().__init__(
            f"run {run}, trajectory {trajectory}: the stored row is damaged ({reason}); "
            "record the run again (replays skip the row)"
        )
        self.run, self.trajectory, self.reason = run, trajectory, reason


class DamagedTrajectoryWarning(UserWarning):
    """A replay skipped a damaged trajectory row (the message names the run and the row)."""


class TraceArgumentError(TraceError, ValueError):
    """A value given to the trace store is outside what it accepts."""

    summary = "a value given to the trace store is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"


class TraceUnknownKey(TraceError, KeyError):
    """A name that the trace store does not know; the message lists the known ones."""

    summary = "a name that the trace store does not know"
    hint = "use one of the names the message lists"


class TraceStateError(TraceError, RuntimeError):
    """The trace store was used out of order; the message says what must happen first."""

    summary = "the trace store was used out of order"
    hint = "the message says what must happen first"


class SceneFileMissing(TraceError):  # noqa: N818 - reads as what is missing
    """A stored scene's body was loaded from a mesh or URDF file that is not on this
    machine, neither in the installed robocram nor at the path it ran with."""

    def __init__(self, body: str, path: Path) -> None:
        super().__init__(
            f"body {body!r} of this trace was loaded from {path}, which is not there (nor in "
            "the installed robocram's package): put the file back at that path, or trace "
            "the run again"
        )
        self.body, self.path = body, path

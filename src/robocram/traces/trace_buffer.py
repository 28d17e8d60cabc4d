"""Rows a tracer holds in memory until its next flush, and the one transaction that writes them.

Task ids are known before anything is written (:func:`~robocram.traces.schema.task_key`:
the run's id and the task's start order), so a flush inserts the new tasks of all runs, and
updates the ones written while running, with one executemany per table. A run's own row is
inserted by its first flush, which is where its id comes from.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from sqlalchemy import Connection, insert

from robocram.costmaps import Costmap
from robocram.motion import JointTrajectory
from robocram.traces.costmap_record import costmap_row
from robocram.traces.errors import TraceStateError
from robocram.traces.robot_model_record import INSERT_DESCRIPTION, INSERT_MODEL
from robocram.traces.schema import (
    Base,
    CostmapRow,
    DesignatorPropertyRow,
    RunRow,
    TaskRow,
    TrajectoryRow,
    WorldStateRow,
    new_id,
    table,
    task_key,
)
from robocram.traces.trajectory_record import trajectory_row
from robocram.traces.world_record import StoredWorldState, state_row

OUTCOME = (
    "status",
    "end",
    "result",
    "failure_type",
    "failure_message",
    "failure_source",
    "designator_kind",
    "designator_type",
)


def _insert_sql(model: type[Base], generated: str | None = None) -> str:
    """``INSERT`` of the columns of ``model``'s table but ``generated``, named parameters."""
    columns = [c.name for c in table(model).columns if c.name != generated]
    names = ", ".join(f'"{c}"' for c in columns)
    return f"INSERT INTO {model.__tablename__} ({names}) VALUES (:{', :'.join(columns)})"


# Plain SQL run on the driver's connection inside SQLAlchemy's transaction: the hot path of
# a traced plan, where SQLAlchemy's per-statement work cost more than SQLite's.
_INSERT_TASKS = _insert_sql(TaskRow)
_INSERT_PROPERTIES = _insert_sql(DesignatorPropertyRow)
_INSERT_STATES = _insert_sql(WorldStateRow, generated="id")
_INSERT_COSTMAPS = _insert_sql(CostmapRow, generated="id")
_INSERT_TRAJECTORIES = _insert_sql(TrajectoryRow, generated="id")
_FINISH_TASKS = (
    f"UPDATE {TaskRow.__tablename__} SET "
    + ", ".join(f'"{name}" = :{name}' for name in OUTCOME)
    + " WHERE id = :id"
)
_FINISH_RUN = f'UPDATE {RunRow.__tablename__} SET status = :status, "end" = :end WHERE id = :id'
_INSERT_RUN = insert(table(RunRow))  # once per run: SQLAlchemy returns the new id


@dataclass
class RunBuffer:
    """One run: its row until the first flush, then its id; its next task's start order."""

    row: dict[str, Any]
    run_id: int | None = None
    started: int = 0  # tasks started so far: the next one's order
    executed: int = 0  # trajectories reported so far: the next one's sequence number
    ended: tuple[str, float | None] = ("running", None)  # (status, end) of the top level
    scene: frozenset[str] = frozenset()  # the bodies of its scene: others are kept as added
    sim_time: float | None = None  # [s] the world's simulated time at its last state kept

    def key(self, order: int) -> int:
        """The database id of this run's ``order``-th task (the run must have been written)."""
        if self.run_id is None:
            raise TraceStateError("a run's task ids are known once its row is written")
        return task_key(self.run_id, order)


@dataclass
class TaskEntry:
    """A task the tracer knows: its run and order, its start row, its outcome when ended."""

    run: RunBuffer
    order: int
    parent: int | None  # the parent's order in the run
    start: dict[str, Any]
    written: bool = False  # its start row is in the database
    outcome: dict[str, Any] | None = None
    properties: list[tuple[str, str]] = field(default_factory=list)  # (key, JSON value)


@dataclass
class Pending:
    """What the next flush writes, in the order it happened."""

    runs: list[RunBuffer] = field(default_factory=list)  # rows not written yet
    tasks: list[TaskEntry] = field(default_factory=list)  # started or ended since
    states: list[tuple[TaskEntry | None, RunBuffer, StoredWorldState]] = field(default_factory=list)
    ended_runs: list[RunBuffer] = field(default_factory=list)
    costmaps: list[tuple[TaskEntry, float, Any, Costmap]] = field(default_factory=list)
    trajectories: list[TrajectoryEntry] = field(default_factory=list)
    robot_models: list[dict[str, str]] = field(default_factory=list)  # robot_models rows
    robot_descriptions: list[dict[str, str]] = field(default_factory=list)  # of file robots

    def __bool__(self) -> bool:
        return bool(
            self.runs
            or self.tasks
            or self.states
            or self.ended_runs
            or self.costmaps
            or self.trajectories
            or self.robot_models
            or self.robot_descriptions
        )


@dataclass(frozen=True)
class TrajectoryEntry:
    """An executed trajectory: the task it ran in, its number in the run, when reported."""

    task: TaskEntry
    sequence: int
    time: float  # [s] since the epoch
    trajectory: JointTrajectory


def write(connection: Connection, pending: Pending) -> None:
    """Write ``pending`` inside the caller's transaction: runs, tasks, states, run ends, ...

    The caller holds the tracer's lock, so no entry changes while it is written.
    """
    for run in pending.runs:
        run.run_id = new_id(connection.execute(_INSERT_RUN, run.row))
    cursor = connection.connection.driver_connection.cursor()  # type: ignore[union-attr]
    tasks = list({id(e): e for e in pending.tasks}.values())  # started and ended: once
    fresh = [_task_row(e) for e in tasks if not e.written]
    ended = [{"id": e.run.key(e.order), **e.outcome} for e in tasks if e.written and e.outcome]
    for entry in tasks:
        entry.written = True
    properties = [
        {"task_id": e.run.key(e.order), "position": i, "key": key, "value": value}
        for e in tasks
        for i, (key, value) in enumerate(e.properties)
    ]
    states = [
        state_row(_run_id(run), None if e is None else run.key(e.order), state)
        for e, run, state in pending.states
    ]
    ends = [{"id": _run_id(r), "status": r.ended[0], "end": r.ended[1]} for r in pending.ended_runs]
    costmaps = [
        costmap_row(_run_id(e.run), e.run.key(e.order), time, designator, costmap)
        for e, time, designator, costmap in pending.costmaps
    ]
    trajectories = [
        trajectory_row(
            _run_id(t.task.run), t.task.run.key(t.task.order), t.sequence, t.time, t.trajectory
        )
        for t in pending.trajectories
    ]
    for sql, rows in (
        (_INSERT_TASKS, fresh),
        (_FINISH_TASKS, ended),
        (_INSERT_PROPERTIES, properties),
        (_INSERT_STATES, states),
        (_FINISH_RUN, ends),
        (_INSERT_COSTMAPS, costmaps),
        (_INSERT_TRAJECTORIES, trajectories),
        (INSERT_MODEL, pending.robot_models),
        (INSERT_DESCRIPTION, pending.robot_descriptions),
    ):
        if rows:
            cursor.executemany(sql, rows)
    cursor.close()


def _task_row(entry: TaskEntry) -> dict[str, Any]:
    run = entry.run
    parent = None if entry.parent is None else run.key(entry.parent)
    row = {"id": run.key(entry.order), "run_id": _run_id(run), "parent_id": parent}
    row |= entry.start
    if entry.outcome is not None:
        row |= entry.outcome
    else:
        row |= dict.fromkeys(OUTCOME)
        row["status"] = entry.start["status"]
    return row


def _run_id(run: RunBuffer) -> int:
    if run.run_id is None:
        raise TraceStateError("a run's row is written before its tasks")
    return run.run_id

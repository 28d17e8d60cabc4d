"""Questions to a trace database: runs, task trees, failures, durations, world at time t."""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import TYPE_CHECKING

from sqlalchemy import case, func, select

from robocram.execution import TaskSnapshot, TaskStatus
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import NoWorldState, UnknownRun
from robocram.traces.schema import DesignatorPropertyRow, RunRow, TaskRow, WorldStateRow

if TYPE_CHECKING:  # loading a world state needs the physics world; listing runs does not
    from robocram.traces.world_record import StoredWorldState


@dataclass(frozen=True)
class RunSummary:
    """One stored run: id, name, outcome, times [s since the epoch] and counts."""

    id: int
    name: str
    status: str
    start: float
    end: float | None
    tasks: int
    failed_tasks: int
    world_states: int


@dataclass(frozen=True)
class FailureRecord:
    """A task that failed where its failure was raised (not the ancestors it passed)."""

    run: int
    path: str
    type: str
    message: str
    start: float | None
    end: float | None


@dataclass(frozen=True)
class DurationStats:
    """Durations [s] of the finished tasks of one kind, e.g. ``motion moving-tcp``."""

    count: int
    total: float
    mean: float
    max: float


def run_ids(db: TraceDatabase) -> list[int]:
    """The ids of all runs, oldest first."""
    with db.read() as session:
        return list(session.scalars(select(RunRow.id).order_by(RunRow.id)))


def require_run(db: TraceDatabase, run: int) -> RunRow:
    """The run row ``run``; UnknownRun (listing the runs) if there is none."""
    with db.read() as session:
        row = session.get(RunRow, run)
    if row is None:
        raise UnknownRun(db.path, run, run_ids(db))
    return row


def runs(db: TraceDatabase) -> list[RunSummary]:
    """Every run with its task, failure and world-state counts, oldest first."""
    failed = func.sum(case((TaskRow.status == TaskStatus.FAILED.value, 1), else_=0))
    states = select(func.count()).where(WorldStateRow.run_id == RunRow.id).scalar_subquery()
    query = (
        select(RunRow, func.count(TaskRow.id), failed, states)
        .outerjoin(TaskRow, TaskRow.run_id == RunRow.id)
        .group_by(RunRow.id)
        .order_by(RunRow.id)
    )
    with db.read() as session:
        return [
            RunSummary(r.id, r.name, r.status, r.start, r.end, n, int(f or 0), int(s))
            for r, n, f, s in session.execute(query)
        ]


def task_tree(db: TraceDatabase, run: int) -> TaskSnapshot:
    """The run's task tree as it was stored, equal to the live tree's snapshot."""
    require_run(db, run)
    with db.read() as session:
        rows = list(session.scalars(select(TaskRow).where(TaskRow.run_id == run)))
    children: dict[int | None, list[TaskRow]] = {}
    for row in rows:
        children.setdefault(row.parent_id, []).append(row)

    def build(row: TaskRow) -> TaskSnapshot:
        kids = sorted(children.get(row.id, []), key=lambda r: r.position)
        return TaskSnapshot(
            name=row.name,
            path=row.path,
            status=TaskStatus(row.status),
            start_time=row.start,
            end_time=row.end,
            result=row.result,
            failure_type=row.failure_type,
            failure_message=row.failure_message,
            failure_source=row.failure_source,
            tags=tuple(json.loads(row.tags)),
            children=tuple(build(kid) for kid in kids),
        )

    return build(children[None][0])


def failures(
    db: TraceDatabase, failure_type: str | None = None, run: int | None = None
) -> list[FailureRecord]:
    """Failures at their source task, optionally of one type or run, in time order."""
    query = select(TaskRow).where(
        TaskRow.status == TaskStatus.FAILED.value, TaskRow.failure_source == TaskRow.path
    )
    if failure_type is not None:
        query = query.where(TaskRow.failure_type == failure_type)
    if run is not None:
        require_run(db, run)
        query = query.where(TaskRow.run_id == run)
    with db.read() as session:
        return [
            FailureRecord(
                r.run_id, r.path, r.failure_type or "", r.failure_message or "", r.start, r.end
            )
            for r in session.scalars(query.order_by(TaskRow.start, TaskRow.id))
        ]


def failure_counts(db: TraceDatabase) -> dict[str, int]:
    """How often each failure type was raised (at its source), most frequent first."""
    return _count_by_type(failures(db))


def _count_by_type(records: list[FailureRecord]) -> dict[str, int]:
    counts: dict[str, int] = {}
    for record in records:
        counts[record.type] = counts.get(record.type, 0) + 1
    return dict(sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))


def durations(db: TraceDatabase, run: int | None = None) -> dict[str, DurationStats]:
    """Duration statistics per performed action or motion type (``"motion looking"``)."""
    took = TaskRow.end - TaskRow.start
    query = (
        select(
            TaskRow.designator_kind,
            TaskRow.designator_type,
            func.count(),
            func.sum(took),
            func.max(took),
        )
        .where(TaskRow.designator_kind.is_not(None), TaskRow.end.is_not(None))
        .group_by(TaskRow.designator_kind, TaskRow.designator_type)
    )
    if run is not None:
        require_run(db, run)
        query = query.where(TaskRow.run_id == run)
    with db.read() as session:
        return {
            f"{kind} {kind_type}": DurationStats(
                n, total or 0.0, (total or 0.0) / n, longest or 0.0
            )
            for kind, kind_type, n, total, longest in session.execute(query)
        }


def world_state_at(db: TraceDatabase, run: int, time: float) -> StoredWorldState:
    """The run's world as last stored at or before ``time`` [s since the epoch]."""
    require_run(db, run)
    query = (
        select(WorldStateRow.id)
        .where(WorldStateRow.run_id == run, WorldStateRow.time <= time)
        .order_by(WorldStateRow.time.desc(), WorldStateRow.id.desc())
        .limit(1)
    )
    with db.read() as session:
        state_id = session.scalar(query)
        if state_id is None:
            raise NoWorldState(run, time)
        from robocram.traces.world_record import load_world_state  # the physics, when asked

        return load_world_state(session, state_id)


def world_state_times(db: TraceDatabase, run: int) -> list[tuple[int, float, str | None]]:
    """(state id, time [s since the epoch], path of the motion) of each stored state."""
    require_run(db, run)
    query = (
        select(WorldStateRow.id, WorldStateRow.time, TaskRow.path)
        .outerjoin(TaskRow, TaskRow.id == WorldStateRow.task_id)
        .where(WorldStateRow.run_id == run)
        .order_by(WorldStateRow.time, WorldStateRow.id)
    )
    with db.read() as session:
        return [(i, t, p) for i, t, p in session.execute(query)]


def designator_properties(db: TraceDatabase, run: int, path: str) -> list[tuple[str, object]]:
    """The (key, value) properties of the designator the task at ``path`` performed."""
    query = (
        select(DesignatorPropertyRow.key, DesignatorPropertyRow.value)
        .join(TaskRow, TaskRow.id == DesignatorPropertyRow.task_id)
        .where(TaskRow.run_id == run, TaskRow.path == path)
        .order_by(DesignatorPropertyRow.position)
    )
    with db.read() as session:
        return [(key, json.loads(value)) for key, value in session.execute(query)]

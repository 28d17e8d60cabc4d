"""The tracer: a task listener that writes each run's tasks and world states as they happen.

Every task start and every task end is its own committed transaction, so a run that dies
half-way leaves all it finished (and what was running, marked running) readable. After
each motion the world's state is stored in the transaction of the motion's end; the run's
first state is stored when it starts.
"""

from __future__ import annotations

import json
import os
import threading
from collections.abc import Iterator
from contextlib import contextmanager, nullcontext
from pathlib import Path
from typing import Any

from sqlalchemy import Connection, bindparam, insert, update

from robocram.designators import ActionDesignator, Designator, MotionDesignator
from robocram.execution import Task, TaskListener, TaskSnapshot, listening
from robocram.traces.database import TraceDatabase
from robocram.traces.json_values import dumps
from robocram.traces.schema import DesignatorPropertyRow, RunRow, TaskRow, new_id, table
from robocram.traces.world_record import StoredWorldState, insert_world_state, scene_of
from robocram.world import World

TRACE_ENV = "ROBOCRAM_TRACE"
_TASKS = table(TaskRow)
_RUNS = table(RunRow)
_OUTCOME = (
    "status",
    "end",
    "result",
    "failure_type",
    "failure_message",
    "failure_source",
    "designator_kind",
    "designator_type",
)
# Statements built once: building one per call cost ten times the SQLite work.
_INSERT_TASK = insert(_TASKS)
_INSERT_RUN = insert(_RUNS)
_INSERT_PROPERTY = insert(table(DesignatorPropertyRow))
_FINISH_TASK = (
    update(_TASKS)
    .where(_TASKS.c.id == bindparam("row_id"))
    .values({name: bindparam(f"new_{name}") for name in _OUTCOME})
)
_FINISH_RUN = (
    update(_RUNS)
    .where(_RUNS.c.id == bindparam("run_id"))
    .values(status=bindparam("new_status"), end=bindparam("new_end"))
)  # environment option: trace top levels to this database file


class Tracer(TaskListener):
    """Writes the task trees of the top levels it sees (and ``world``'s states) to ``db``."""

    def __init__(self, db: TraceDatabase, world: World | None = None) -> None:
        self.db = db
        self.world = world
        self.runs: list[int] = []  # ids of the runs written, in start order
        self._rows: dict[int, tuple[Task, int, int]] = {}  # id(task) -> (task, row, run)
        self._designators: dict[int, Designator] = {}
        self._lock = threading.Lock()

    def task_started(self, task: Task) -> None:
        """Insert the task (and, for a new top level, its run and first world state)."""
        with self._lock:
            parent = self._rows.get(id(task.parent)) if task.parent is not None else None
        with self.db.append() as connection:
            run_id = self._new_run(connection, task) if parent is None else parent[2]
            row = {
                "run_id": run_id,
                "parent_id": None if parent is None else parent[1],
                "position": _position(task) if parent is not None else 0,
                "name": task.name,
                "path": task.path,
                "status": task.status.value,
                "start": task.start_time,
                "tags": json.dumps(sorted(task.tags)),
            }
            inserted = connection.execute(_INSERT_TASK, row)
        with self._lock:
            self._rows[id(task)] = (task, new_id(inserted), run_id)

    def _new_run(self, connection: Connection, task: Task) -> int:
        scene = scene_of(self.world) if self.world is not None else None
        row = {"name": task.name, "status": task.status.value, "start": task.start_time}
        inserted = connection.execute(_INSERT_RUN, {**row, "pid": os.getpid(), "scene": scene})
        run_id = new_id(inserted)
        if self.world is not None:
            state = StoredWorldState.capture(self.world, task.start_time or 0.0)
            insert_world_state(connection, run_id, None, state)
        self.runs.append(run_id)
        return run_id

    def performing(self, task: Task, designator: Any) -> None:
        """Remember the designator; it is written with the task's end."""
        if isinstance(designator, Designator):
            with self._lock:
                self._designators[id(task)] = designator

    def task_finished(self, task: Task) -> None:
        """Write the outcome; after a motion, also the world's state."""
        with self._lock:
            known = self._rows.pop(id(task), None)
            designator = self._designators.pop(id(task), None)
        if known is None:
            return
        _, row_id, run_id = known
        snap = TaskSnapshot.of(task)
        state = None
        if isinstance(designator, MotionDesignator) and self.world is not None:
            state = StoredWorldState.capture(self.world, task.end_time or 0.0)
        with self.db.append() as connection:
            outcome = {f"new_{k}": v for k, v in _outcome(snap, designator).items()}
            connection.execute(_FINISH_TASK, {"row_id": row_id, **outcome})
            if designator is not None:
                _write_properties(connection, row_id, designator)
            if state is not None:
                insert_world_state(connection, run_id, row_id, state)
            if task.parent is None or run_id != self._run_of(task.parent):
                values = {"new_status": snap.status.value, "new_end": snap.end_time}
                connection.execute(_FINISH_RUN, {"run_id": run_id, **values})

    def _run_of(self, task: Task) -> int | None:
        with self._lock:
            known = self._rows.get(id(task))
        return None if known is None else known[2]


def _position(task: Task) -> int:
    assert task.parent is not None
    return next(i for i, child in enumerate(list(task.parent.children)) if child is task)


def _outcome(snap: TaskSnapshot, designator: Designator | None) -> dict[str, Any]:
    kind = None
    if isinstance(designator, MotionDesignator | ActionDesignator):
        kind = "motion" if isinstance(designator, MotionDesignator) else "action"
    return {
        "status": snap.status.value,
        "end": snap.end_time,
        "result": snap.result,
        "failure_type": snap.failure_type,
        "failure_message": snap.failure_message,
        "failure_source": snap.failure_source,
        "designator_kind": kind,
        "designator_type": None if designator is None else str(designator.type),
    }


def _write_properties(connection: Connection, task_id: int, designator: Designator) -> None:
    rows = [
        {"task_id": task_id, "position": i, "key": str(key), "value": dumps(value)}
        for i, (key, value) in enumerate(designator.properties)
    ]
    if rows:
        connection.execute(_INSERT_PROPERTY, rows)


@contextmanager
def trace_to(path: str | Path, world: World | None = None) -> Iterator[Tracer]:
    """Trace every top level run inside the block to the SQLite file ``path``.

    With ``world``, its state is stored at the start of each run and after each motion.
    """
    with TraceDatabase(path) as db, listening(Tracer(db, world)) as tracer:
        assert isinstance(tracer, Tracer)
        yield tracer


def trace_from_environment(world: World | None = None) -> Any:
    """``trace_to($ROBOCRAM_TRACE, world)`` if that variable is set, else a no-op block."""
    path = os.environ.get(TRACE_ENV)
    return trace_to(path, world) if path else nullcontext(None)

"""The tracer: a task listener that writes each run's tasks and world states in batches.

Rows are kept in memory, with every task's id known up front, and written in one
transaction (one executemany per table) when a task starts after a motion has ended (so
at every motion boundary), when ``FLUSH_CPU`` seconds of CPU time have passed since the
last write, and at the run's end. A run killed half-way thus leaves readable every task
that ended before the last motion did, and the tasks running then, marked running. World
states are captured after each motion and at the run's start; every trajectory reported
with :func:`robocram.motion.report_executed` inside a traced run is kept with its task
(one reported outside any traced run has no run to belong to and is not kept).
"""

from __future__ import annotations

import json
import os
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager, nullcontext
from pathlib import Path
from typing import Any

from robocram.costmaps import Costmap, observing_costmaps
from robocram.designators import ActionDesignator, Designator, MotionDesignator
from robocram.execution import Task, TaskListener, TaskSnapshot, current_task, listening
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.traces.database import TraceDatabase
from robocram.traces.json_values import dumps
from robocram.traces.robot_model_record import description_row, model_row
from robocram.traces.trace_buffer import Pending, RunBuffer, TaskEntry, TrajectoryEntry, write
from robocram.traces.world_record import StoredWorldState, scene_names, scene_of
from robocram.world import World

TRACE_ENV = "ROBOCRAM_TRACE"  # environment option: trace top levels to this database file
FLUSH_CPU = 0.5  # [s] of process CPU time after which pending rows are written anyway


class Tracer(TaskListener):
    """Writes the task trees of the top levels it sees (and ``world``'s states) to ``db``."""

    def __init__(self, db: TraceDatabase, world: World | None = None) -> None:
        self.db = db
        self.world = world
        self.runs: list[int] = []  # ids of the runs written, in start order
        self._entries: dict[int, TaskEntry] = {}  # id(task) -> entry, while it runs
        self._designators: dict[int, Designator] = {}
        self._pending = Pending()
        self._motion_ended = False  # since the last write
        self._lock = threading.Lock()  # guards the entries and the pending rows; writes
        self._last_flush = time.process_time()
        self._models_kept: set[str] = set()  # digests of URDFs, descriptions written or pending

    def task_started(self, task: Task) -> None:
        """Give the task its id (its run's start order); a new top level starts a run."""
        parent = task.parent
        with self._lock:
            above = self._entries.get(id(parent)) if parent is not None else None
            run = self._new_run(task) if above is None else above.run
            start = {
                "position": _position(task) if above is not None else 0,
                "name": task.name,
                "path": task.path,
                "status": task.status.value,
                "start": task.start_time,
                "tags": json.dumps(sorted(task.tags)),
            }
            entry = TaskEntry(run, run.started, None if above is None else above.order, start)
            run.started += 1
            self._entries[id(task)] = entry
            self._pending.tasks.append(entry)
            due = self._motion_ended or time.process_time() - self._last_flush >= FLUSH_CPU
        if due:
            self.flush()

    def _new_run(self, task: Task) -> RunBuffer:
        scene = scene_of(self.world) if self.world is not None else None
        row = {"name": task.name, "status": task.status.value, "start": task.start_time}
        names = scene_names(scene) if scene is not None else frozenset()
        run = RunBuffer({**row, "pid": os.getpid(), "scene": scene}, scene=names)
        self._pending.runs.append(run)
        if self.world is not None:
            state = StoredWorldState.capture(self.world, task.start_time or 0.0, names)
            self._pending.states.append((None, run, state))
            run.sim_time = state.sim_time
            self._keep_models(self.world)
        return run

    def _keep_models(self, world: World) -> None:
        """Queue the URDF of each robot not yet written by this tracer (once per content),
        and the description of each robot read from a file."""
        for robot in world.robots():
            desc = robot.description
            rows = [(model_row(desc.name, desc.model), self._pending.robot_models)]
            if desc.source:
                rows.append((description_row(desc), self._pending.robot_descriptions))
            for row, pending in rows:
                if row["digest"] not in self._models_kept:
                    self._models_kept.add(row["digest"])
                    pending.append(row)

    def performing(self, task: Task, designator: Any) -> None:
        """Remember the designator; it is written with the task's end. Before a motion, keep
        the world's state if it was simulated since the last one kept (an object let go
        settles): the audit replays the motion on the world as it was, not as it was
        before the object dropped 7 mm (a Stretch's parking grazed a settled bowl by 1.9 mm
        and went 6 mm into it as it hung before)."""
        if isinstance(designator, Designator):
            with self._lock:
                self._designators[id(task)] = designator
        if isinstance(designator, MotionDesignator) and self.world is not None:
            self._keep_if_simulated(task, self.world)

    def _keep_if_simulated(self, task: Task, world: World) -> None:
        with self._lock:
            entry = self._entries.get(id(task))
        if entry is None or world.physics.time == entry.run.sim_time:
            return
        state = StoredWorldState.capture(world, task.start_time or 0.0, entry.run.scene)
        with self._lock:
            self._pending.states.append((entry, entry.run, state))
            entry.run.sim_time = state.sim_time

    def task_finished(self, task: Task) -> None:
        """Keep the outcome (and after a motion the world's state); a run's end writes."""
        with self._lock:
            entry = self._entries.pop(id(task), None)
            designator = self._designators.pop(id(task), None)
        if entry is None:
            return
        state = None
        if isinstance(designator, MotionDesignator) and self.world is not None:
            state = StoredWorldState.capture(self.world, task.end_time or 0.0, entry.run.scene)
        snap = TaskSnapshot.of(task)
        properties = [] if designator is None else _properties(designator)
        top = entry.parent is None
        with self._lock:
            entry.outcome = _outcome(snap, designator)
            entry.properties = properties
            self._pending.tasks.append(entry)
            if state is not None:
                self._pending.states.append((entry, entry.run, state))
                entry.run.sim_time = state.sim_time
                self._motion_ended = True
            if top:
                entry.run.ended = (snap.status.value, snap.end_time)
                self._pending.ended_runs.append(entry.run)
        if top:
            self.flush()

    def costmap_built(self, designator: Any, costmap: Costmap) -> None:
        """Keep a costmap a location was resolved through, with the task that asked."""
        task = current_task()
        with self._lock:
            entry = self._entries.get(id(task)) if task is not None else None
            if entry is not None:
                self._pending.costmaps.append((entry, time.time(), designator, costmap))

    def trajectory_executed(self, trajectory: JointTrajectory) -> None:
        """Keep an executed trajectory with the innermost running task the tracer knows.

        It is written with the next flush, in the transaction of its motion's end.
        """
        reported = time.time()
        task = current_task()
        with self._lock:
            entry = None
            while task is not None and entry is None:
                entry = self._entries.get(id(task))
                task = task.parent
            if entry is not None:
                sequence, entry.run.executed = entry.run.executed, entry.run.executed + 1
                item = TrajectoryEntry(entry, sequence, reported, trajectory)
                self._pending.trajectories.append(item)

    def flush(self) -> None:
        """Write every pending row now, in one transaction."""
        with self._lock:
            pending, self._pending = self._pending, Pending()
            self._motion_ended = False
            if pending:
                with self.db.append() as connection:
                    write(connection, pending)
                self.runs.extend(r.run_id for r in pending.runs if r.run_id is not None)
            self._last_flush = time.process_time()


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


def _properties(designator: Designator) -> list[tuple[str, str]]:
    return [(str(key), dumps(value)) for key, value in designator.properties]


@contextmanager
def trace_to(path: str | Path, world: World | None = None) -> Iterator[Tracer]:
    """Trace every top level run inside the block to the SQLite file ``path``.

    With ``world``, its state is stored at the start of each run and after each motion.
    The costmaps location designators are resolved through, and the trajectories the
    robots execute, are stored too.
    """
    with TraceDatabase(path) as db, listening(Tracer(db, world)) as tracer:
        assert isinstance(tracer, Tracer)
        try:
            with (
                observing_costmaps(tracer.costmap_built),
                trajectory_listener(tracer.trajectory_executed),
            ):
                yield tracer
        finally:
            tracer.flush()  # what a block left running (a stopped thread) is kept too


def trace_from_environment(world: World | None = None) -> Any:
    """``trace_to($ROBOCRAM_TRACE, world)`` if that variable is set, else a no-op block."""
    path = os.environ.get(TRACE_ENV)
    return trace_to(path, world) if path else nullcontext(None)

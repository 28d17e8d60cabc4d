"""Execution traces: every top-level run's task tree and world states, kept in SQLite.

``with trace_to("runs.db", world=world):`` writes each run's tasks, and the world's state
after every motion, in one transaction per motion, so a run can be queried, exported and
replayed later, and a run killed half-way keeps what it finished.
Several processes may append to one file (WAL mode, one writer at a time).
"""

from robocram.traces.costmap_record import StoredCostmap, run_costmaps
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import (
    NotATraceDatabase,
    NoWorldState,
    SchemaVersionMismatch,
    TraceError,
    UnknownRun,
)
from robocram.traces.queries import (
    DurationStats,
    FailureRecord,
    RunSummary,
    designator_properties,
    durations,
    failure_counts,
    failures,
    require_run,
    run_ids,
    runs,
    task_tree,
    world_state_at,
    world_state_times,
)
from robocram.traces.schema import SCHEMA_VERSION
from robocram.traces.tracer import TRACE_ENV, Tracer, trace_from_environment, trace_to
from robocram.traces.world_record import StoredWorldState, build_scene, scene_of

__all__ = [
    "SCHEMA_VERSION",
    "TRACE_ENV",
    "DurationStats",
    "FailureRecord",
    "NoWorldState",
    "NotATraceDatabase",
    "RunSummary",
    "SchemaVersionMismatch",
    "StoredCostmap",
    "StoredWorldState",
    "TraceDatabase",
    "TraceError",
    "Tracer",
    "UnknownRun",
    "build_scene",
    "designator_properties",
    "durations",
    "failure_counts",
    "failures",
    "require_run",
    "run_costmaps",
    "run_ids",
    "runs",
    "scene_of",
    "task_tree",
    "trace_from_environment",
    "trace_to",
    "world_state_at",
    "world_state_times",
]

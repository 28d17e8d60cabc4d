"""Execution traces: every top-level run's task tree and world states, kept in SQLite.

``with trace_to("runs.db", world=world):`` writes each run's tasks, the world's state
after every motion and every executed trajectory, in one transaction per motion, so a run
can be queried, exported, replayed and animated later, and a run killed half-way keeps
what it finished.
Several processes may append to one file (WAL mode, one writer at a time).
"""

from robocram.traces.costmap_record import StoredCostmap, run_costmaps
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import (
    DamagedTrace,
    MissingRobotDescription,
    NotATraceDatabase,
    NoWorldState,
    SchemaVersionMismatch,
    TraceError,
    TraceLocked,
    TraceStorageError,
    UnknownRun,
)
from robocram.traces.mcap_export import export_mcap
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
from robocram.traces.replay_clock import ReplayClock
from robocram.traces.run_animation import RunAnimation, animate_run
from robocram.traces.run_replay import ReplayFrame, replay_frames, robot_in, set_robot_joints
from robocram.traces.schema import SCHEMA_VERSION
from robocram.traces.tracer import TRACE_ENV, Tracer, trace_from_environment, trace_to
from robocram.traces.trajectory_record import StoredTrajectory, replay_clock, run_trajectories
from robocram.traces.world_record import StoredWorldState, build_scene, scene_of

__all__ = [
    "DamagedTrace",
    "DurationStats",
    "FailureRecord",
    "NoWorldState",
    "MissingRobotDescription",
    "NotATraceDatabase",
    "ReplayClock",
    "ReplayFrame",
    "RunAnimation",
    "RunSummary",
    "SCHEMA_VERSION",
    "SchemaVersionMismatch",
    "StoredCostmap",
    "StoredTrajectory",
    "StoredWorldState",
    "TRACE_ENV",
    "TraceDatabase",
    "TraceError",
    "TraceLocked",
    "TraceStorageError",
    "Tracer",
    "UnknownRun",
    "animate_run",
    "build_scene",
    "designator_properties",
    "durations",
    "export_mcap",
    "failure_counts",
    "failures",
    "replay_clock",
    "replay_frames",
    "require_run",
    "robot_in",
    "run_costmaps",
    "run_ids",
    "run_trajectories",
    "runs",
    "scene_of",
    "set_robot_joints",
    "task_tree",
    "trace_from_environment",
    "trace_to",
    "world_state_at",
    "world_state_times",
]

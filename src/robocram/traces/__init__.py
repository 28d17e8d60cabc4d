"""Execution traces: every top-level run's task tree and world states, kept in SQLite.

``with trace_to("runs.db", world=world):`` writes each run's tasks, the world's state
after every motion and every executed trajectory, in one transaction per motion, so a run
can be queried, exported, replayed and animated later, and a run killed half-way keeps
what it finished.
Several processes may append to one file (WAL mode, one writer at a time).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

# stdlib only; loaded first, so the function of the same name below keeps its name
import robocram.traces.replay_clock as _replay_clock_module  # noqa: F401

if TYPE_CHECKING:  # the names, for type checkers; at run time each loads on first use
    from robocram.traces.audit_bounds import AuditBounds
    from robocram.traces.audit_findings import AuditFinding, AuditReport, FindingKind
    from robocram.traces.costmap_record import StoredCostmap, run_costmaps
    from robocram.traces.database import TraceDatabase
    from robocram.traces.errors import (
        DamagedTrace,
        DamagedTrajectory,
        DamagedTrajectoryWarning,
        MissingRobotDescription,
        NoSceneStored,
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
    from robocram.traces.trajectory_audit import audit_run, audit_runs
    from robocram.traces.trajectory_record import StoredTrajectory, run_trajectories
    from robocram.traces.world_record import StoredWorldState, build_scene, scene_of

_WHERE = {  # name -> the module that defines it: `robocram runs list` needs no physics
    "AuditBounds": "robocram.traces.audit_bounds",
    "AuditFinding": "robocram.traces.audit_findings",
    "AuditReport": "robocram.traces.audit_findings",
    "DamagedTrace": "robocram.traces.errors",
    "DamagedTrajectory": "robocram.traces.errors",
    "DamagedTrajectoryWarning": "robocram.traces.errors",
    "DurationStats": "robocram.traces.queries",
    "FailureRecord": "robocram.traces.queries",
    "FindingKind": "robocram.traces.audit_findings",
    "MissingRobotDescription": "robocram.traces.errors",
    "NoSceneStored": "robocram.traces.errors",
    "NoWorldState": "robocram.traces.errors",
    "NotATraceDatabase": "robocram.traces.errors",
    "ReplayClock": "robocram.traces.replay_clock",
    "ReplayFrame": "robocram.traces.run_replay",
    "RunAnimation": "robocram.traces.run_animation",
    "RunSummary": "robocram.traces.queries",
    "SCHEMA_VERSION": "robocram.traces.schema",
    "SchemaVersionMismatch": "robocram.traces.errors",
    "StoredCostmap": "robocram.traces.costmap_record",
    "StoredTrajectory": "robocram.traces.trajectory_record",
    "StoredWorldState": "robocram.traces.world_record",
    "TRACE_ENV": "robocram.traces.tracer",
    "TraceDatabase": "robocram.traces.database",
    "TraceError": "robocram.traces.errors",
    "TraceLocked": "robocram.traces.errors",
    "TraceStorageError": "robocram.traces.errors",
    "Tracer": "robocram.traces.tracer",
    "UnknownRun": "robocram.traces.errors",
    "animate_run": "robocram.traces.run_animation",
    "audit_run": "robocram.traces.trajectory_audit",
    "audit_runs": "robocram.traces.trajectory_audit",
    "build_scene": "robocram.traces.world_record",
    "designator_properties": "robocram.traces.queries",
    "durations": "robocram.traces.queries",
    "export_mcap": "robocram.traces.mcap_export",
    "failure_counts": "robocram.traces.queries",
    "failures": "robocram.traces.queries",
    "replay_frames": "robocram.traces.run_replay",
    "require_run": "robocram.traces.queries",
    "robot_in": "robocram.traces.run_replay",
    "run_costmaps": "robocram.traces.costmap_record",
    "run_ids": "robocram.traces.queries",
    "run_trajectories": "robocram.traces.trajectory_record",
    "runs": "robocram.traces.queries",
    "scene_of": "robocram.traces.world_record",
    "set_robot_joints": "robocram.traces.run_replay",
    "task_tree": "robocram.traces.queries",
    "trace_from_environment": "robocram.traces.tracer",
    "trace_to": "robocram.traces.tracer",
    "world_state_at": "robocram.traces.queries",
    "world_state_times": "robocram.traces.queries",
}


def replay_clock(db: TraceDatabase, run: int) -> ReplayClock:
    """The replay clock of run ``run`` (:func:`robocram.traces.trajectory_record.replay_clock`).

    Bound here, after its module of the same name was loaded (above), so that module never
    takes the name's place.
    """
    from robocram.traces.trajectory_record import replay_clock as clock_of

    return clock_of(db, run)


def __getattr__(name: str) -> object:
    """Load the module that defines ``name`` on first use (PEP 562)."""
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module 'robocram.traces' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


__all__ = [
    "AuditBounds",
    "AuditFinding",
    "AuditReport",
    "DamagedTrace",
    "DamagedTrajectory",
    "DamagedTrajectoryWarning",
    "DurationStats",
    "FailureRecord",
    "FindingKind",
    "NoSceneStored",
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
    "audit_run",
    "audit_runs",
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

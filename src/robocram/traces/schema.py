"""The trace database's tables as typed SQLAlchemy 2.0 ORM models.

One run is one top-level task tree. Tasks are rows keyed by a database-wide id made of the
run's id and the task's start order in the run (:func:`task_key`), so a tracer knows every
id before it writes and several processes can append runs to one file; each row names its
parent and its position among the parent's children. World states are stored at motion
boundaries, one row each; executed trajectories one row each, in execution order.
``SCHEMA_VERSION`` changes whenever a table does; a version whose only change is a new
table (:data:`ADDED_TABLES`) or a new nullable column (:data:`ADDED_COLUMNS`) is opened by
adding it.
"""

from __future__ import annotations

from typing import Any, cast

from sqlalchemy import (
    CursorResult,
    Float,
    ForeignKey,
    Index,
    Integer,
    LargeBinary,
    String,
    Table,
    Text,
)
from sqlalchemy.orm import DeclarativeBase, Mapped, mapped_column

from robocram.traces.errors import TraceArgumentError

# 2: world state rows, task ids per run; 3: costmaps; 4: trajectories; 5: URDFs;
# 6: trajectories' allowed contacts; 7: the joints of other objects trajectories carry;
# 8: the bodies a run added after its start (particles, slices), with each world state;
# 9: the descriptions of robots read from files
SCHEMA_VERSION = 9
# version -> tables it added
ADDED_TABLES = {4: ("trajectories",), 5: ("robot_models",), 9: ("robot_descriptions",)}
ADDED_COLUMNS = {  # version -> (table, column)
    6: (("trajectories", "allowed_contacts"),),
    7: (("trajectories", "carried"),),
    8: (("world_states", "added"),),
}


def upgradable(version: int) -> bool:
    """Whether a file of ``version`` opens by adding what later versions added (and only that)."""
    later = range(version + 1, SCHEMA_VERSION + 1)
    added = ADDED_TABLES.keys() | ADDED_COLUMNS.keys()
    return version < SCHEMA_VERSION and all(v in added for v in later)


class Base(DeclarativeBase):
    """Declarative base of the trace tables."""


class SchemaInfo(Base):
    """The one row naming the schema version the file was written with."""

    __tablename__ = "schema_info"
    version: Mapped[int] = mapped_column(Integer, primary_key=True)


class RunRow(Base):
    """A top-level run: its name, outcome, process and the scene it ran in (JSON)."""

    __tablename__ = "runs"
    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    name: Mapped[str] = mapped_column(String)
    status: Mapped[str] = mapped_column(String)
    start: Mapped[float] = mapped_column(Float)  # [s] since the epoch
    end: Mapped[float | None] = mapped_column(Float)  # [s] since the epoch
    pid: Mapped[int] = mapped_column(Integer)
    scene: Mapped[str | None] = mapped_column(Text)  # JSON list of object specs


class TaskRow(Base):
    """One task: where it sits in the tree, its outcome and what it performed."""

    __tablename__ = "tasks"
    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    run_id: Mapped[int] = mapped_column(ForeignKey("runs.id"))
    parent_id: Mapped[int | None] = mapped_column(ForeignKey("tasks.id"))
    position: Mapped[int] = mapped_column(Integer)  # index among the parent's children
    name: Mapped[str] = mapped_column(String)
    path: Mapped[str] = mapped_column(String)
    status: Mapped[str] = mapped_column(String)
    start: Mapped[float | None] = mapped_column(Float)  # [s] since the epoch
    end: Mapped[float | None] = mapped_column(Float)  # [s] since the epoch
    result: Mapped[str | None] = mapped_column(Text)
    failure_type: Mapped[str | None] = mapped_column(String)
    failure_message: Mapped[str | None] = mapped_column(Text)
    failure_source: Mapped[str | None] = mapped_column(String)
    tags: Mapped[str] = mapped_column(Text, default="[]")  # JSON list
    designator_kind: Mapped[str | None] = mapped_column(String)  # "motion", "action", ...
    designator_type: Mapped[str | None] = mapped_column(String)  # e.g. "moving-tcp"

    __table_args__ = (Index("ix_tasks_run", "run_id"), Index("ix_tasks_failure", "failure_type"))


class DesignatorPropertyRow(Base):
    """One property of the designator a PERFORM task ran; the value as JSON."""

    __tablename__ = "designator_properties"
    task_id: Mapped[int] = mapped_column(ForeignKey("tasks.id"), primary_key=True)
    position: Mapped[int] = mapped_column(Integer, primary_key=True)
    key: Mapped[str] = mapped_column(String)
    value: Mapped[str] = mapped_column(Text)


class WorldStateRow(Base):
    """The world at one moment of a run: after a motion, or at the run's start.

    Stored compactly, one row per state: poses, joints and attachments as JSON text
    (Python's float text round-trips exactly, so a restored state is bit-identical). A
    body the run's scene lacks (added mid-run) is stored with its recipe; a body of the
    scene missing from ``poses`` was removed.
    """

    __tablename__ = "world_states"
    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    run_id: Mapped[int] = mapped_column(ForeignKey("runs.id"))
    task_id: Mapped[int | None] = mapped_column(ForeignKey("tasks.id"))
    time: Mapped[float] = mapped_column(Float)  # [s] since the epoch (wall clock)
    sim_time: Mapped[float] = mapped_column(Float)  # [s] of simulated time in the world
    poses: Mapped[str] = mapped_column(Text)  # {object: [x, y, z, qx, qy, qz, qw]} in map
    joints: Mapped[str] = mapped_column(Text)  # {object: {joint: [rad] or [m]}}
    attachments: Mapped[str] = mapped_column(Text)  # [[object, robot, link, pose], ...]
    # JSON {object: body recipe} of the bodies not in the run's scene (added since it
    # started: poured particles, cut slices); NULL (none, or a file before version 8)
    added: Mapped[str | None] = mapped_column(Text, nullable=True)

    __table_args__ = (Index("ix_world_states_run_time", "run_id", "time"),)


class CostmapRow(Base):
    """A costmap a location designator was resolved through, while a task of the run ran.

    The grid's weights and heights are float64 arrays, row-major, zlib-compressed.
    """

    __tablename__ = "costmaps"
    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    run_id: Mapped[int] = mapped_column(ForeignKey("runs.id"))
    task_id: Mapped[int | None] = mapped_column(ForeignKey("tasks.id"))
    time: Mapped[float] = mapped_column(Float)  # [s] since the epoch, when it was built
    designator: Mapped[str] = mapped_column(Text)  # the location designator's description
    origin_x: Mapped[float] = mapped_column(Float)  # [m] map x of cell (0, 0)'s centre
    origin_y: Mapped[float] = mapped_column(Float)  # [m] map y of cell (0, 0)'s centre
    resolution: Mapped[float] = mapped_column(Float)  # [m] cell side
    rows: Mapped[int] = mapped_column(Integer)  # cells along y
    columns: Mapped[int] = mapped_column(Integer)  # cells along x
    weights: Mapped[bytes] = mapped_column(LargeBinary)
    heights: Mapped[bytes] = mapped_column(LargeBinary)  # [m] map z of each cell

    __table_args__ = (Index("ix_costmaps_run_time", "run_id", "time"),)


class TrajectoryRow(Base):
    """A trajectory a robot executed while a task of the run ran, in execution order.

    The points are little-endian float64 arrays, row-major (points x joints): exact, and
    one row per trajectory however many points it has.
    """

    __tablename__ = "trajectories"
    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    run_id: Mapped[int] = mapped_column(ForeignKey("runs.id"))
    task_id: Mapped[int | None] = mapped_column(ForeignKey("tasks.id"))
    sequence: Mapped[int] = mapped_column(Integer)  # execution order in the run, from 0
    time: Mapped[float] = mapped_column(Float)  # [s] since the epoch, when it was reported
    robot: Mapped[str] = mapped_column(String)
    kind: Mapped[str] = mapped_column(String)  # "arm", "cartesian", "base", ...
    joint_names: Mapped[str] = mapped_column(Text)  # JSON list
    times: Mapped[bytes] = mapped_column(LargeBinary)  # [s] from its start, per point
    positions: Mapped[bytes] = mapped_column(LargeBinary)  # [rad | m]
    velocities: Mapped[bytes] = mapped_column(LargeBinary)  # [rad/s | m/s]
    accelerations: Mapped[bytes] = mapped_column(LargeBinary)  # [rad/s^2 | m/s^2]
    # JSON [[robot side, other, depth [m]], ...]; NULL (files before version 6): none
    allowed_contacts: Mapped[str | None] = mapped_column(Text, nullable=True)
    # JSON [[object, joint, start, end], ...]: joints it moved along; NULL (before 7): none
    carried: Mapped[str | None] = mapped_column(Text, nullable=True)

    __table_args__ = (Index("ix_trajectories_run", "run_id", "sequence"),)


class RobotModelRow(Base):
    """The URDF text of a robot a run's scene holds, once per content (its SHA-1 digest).

    A scene names its robots' models by digest, so a thousand runs of one robot store one
    text, and an export shows the robot that ran, whatever the built-in is today.
    """

    __tablename__ = "robot_models"
    digest: Mapped[str] = mapped_column(String, primary_key=True)  # SHA-1 of the text, hex
    name: Mapped[str] = mapped_column(String)  # the description's name
    urdf: Mapped[str] = mapped_column(Text)


class RobotDescriptionRow(Base):
    """The description of a robot read from a file, once per content (its SHA-1 digest).

    With the model's URDF text it builds the robot again when the file has moved, changed
    or stayed on another machine: a scene names it by ``description_digest``.
    """

    __tablename__ = "robot_descriptions"
    digest: Mapped[str] = mapped_column(String, primary_key=True)  # SHA-1 of the JSON, hex
    name: Mapped[str] = mapped_column(String)  # the description's name
    description: Mapped[str] = mapped_column(Text)  # robots.description_json's JSON


TASKS_PER_RUN = 1 << 32  # task keys of one run: run id * TASKS_PER_RUN + start order


def task_key(run_id: int, order: int) -> int:
    """The database-wide id of the ``order``-th task (0: the top level) of run ``run_id``."""
    if not 0 <= order < TASKS_PER_RUN:
        raise TraceArgumentError(f"a run holds at most {TASKS_PER_RUN} tasks, got task {order}")
    return run_id * TASKS_PER_RUN + order


def table(model: type[Base]) -> Table:
    """The Core table of an ORM model: executemany inserts on the tracer's hot path."""
    return cast(Table, model.__table__)


def new_id(result: CursorResult[Any]) -> int:
    """The primary key an INSERT just made."""
    key = result.inserted_primary_key
    if key is None:
        raise TraceArgumentError("the statement inserted no row")
    return int(key[0])

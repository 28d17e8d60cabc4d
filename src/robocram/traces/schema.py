"""The trace database's tables as typed SQLAlchemy 2.0 ORM models.

One run is one top-level task tree. Tasks are rows keyed by a database-wide id (so several
processes can append runs to one file) with their parent and their position among its
children. World states are stored at motion boundaries as rows of object poses, joint
positions and attachments. ``SCHEMA_VERSION`` changes whenever a table does.
"""

from __future__ import annotations

from typing import Any, cast

from sqlalchemy import CursorResult, Float, ForeignKey, Index, Integer, String, Table, Text
from sqlalchemy.orm import DeclarativeBase, Mapped, mapped_column

SCHEMA_VERSION = 1


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
    """The world at one moment of a run: after a motion, or at the run's start."""

    __tablename__ = "world_states"
    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    run_id: Mapped[int] = mapped_column(ForeignKey("runs.id"))
    task_id: Mapped[int | None] = mapped_column(ForeignKey("tasks.id"))
    time: Mapped[float] = mapped_column(Float)  # [s] since the epoch (wall clock)
    sim_time: Mapped[float] = mapped_column(Float)  # [s] of simulated time in the world

    __table_args__ = (Index("ix_world_states_run_time", "run_id", "time"),)


class PoseColumns:
    """A pose as seven columns: position [m] and quaternion (x, y, z, w)."""

    x: Mapped[float] = mapped_column(Float)
    y: Mapped[float] = mapped_column(Float)
    z: Mapped[float] = mapped_column(Float)
    qx: Mapped[float] = mapped_column(Float)
    qy: Mapped[float] = mapped_column(Float)
    qz: Mapped[float] = mapped_column(Float)
    qw: Mapped[float] = mapped_column(Float)


class ObjectPoseRow(PoseColumns, Base):
    """An object's root-link pose in map [m, quaternion xyzw] in one world state."""

    __tablename__ = "object_poses"
    state_id: Mapped[int] = mapped_column(ForeignKey("world_states.id"), primary_key=True)
    object: Mapped[str] = mapped_column(String, primary_key=True)


class JointPositionRow(Base):
    """One movable joint's position [rad or m] in one world state."""

    __tablename__ = "joint_positions"
    state_id: Mapped[int] = mapped_column(ForeignKey("world_states.id"), primary_key=True)
    object: Mapped[str] = mapped_column(String, primary_key=True)
    joint: Mapped[str] = mapped_column(String, primary_key=True)
    position: Mapped[float] = mapped_column(Float)


class AttachmentRow(PoseColumns, Base):
    """An object fixed to a robot link at ``link_T_obj`` [m, quaternion] in one state."""

    __tablename__ = "attachments"
    state_id: Mapped[int] = mapped_column(ForeignKey("world_states.id"), primary_key=True)
    object: Mapped[str] = mapped_column(String, primary_key=True)
    robot: Mapped[str] = mapped_column(String)
    link: Mapped[str] = mapped_column(String)


def table(model: type[Base]) -> Table:
    """The Core table of an ORM model: executemany inserts on the tracer's hot path."""
    return cast(Table, model.__table__)


def new_id(result: CursorResult[Any]) -> int:
    """The primary key an INSERT just made."""
    key = result.inserted_primary_key
    if key is None:
        raise ValueError("the statement inserted no row")
    return int(key[0])

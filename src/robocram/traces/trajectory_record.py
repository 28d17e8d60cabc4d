"""Executed trajectories as the trace store keeps them, and back again.

While a run is traced, every trajectory projection (or a real robot's driver) reports with
:func:`robocram.motion.report_executed` is kept with the task that was running and the wall
time it was reported, so it lies between the world states before and after its motion.
Points are stored as exact float64 arrays, one row per trajectory.
"""

from __future__ import annotations

import json
import warnings
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray
from sqlalchemy import select

from robocram.motion import CarriedJoint, ContactAllowance, JointTrajectory, TrajectoryPoint
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import DamagedTrajectory, DamagedTrajectoryWarning, TraceArgumentError
from robocram.traces.queries import require_run, world_state_times
from robocram.traces.replay_clock import ReplayClock, replay_starts
from robocram.traces.schema import TaskRow, TrajectoryRow


@dataclass(frozen=True)
class StoredTrajectory:
    """A trajectory of a run: what moved, along which points, when, in which task."""

    index: int  # execution order in the run, from 0
    robot: str
    joint_names: tuple[str, ...]
    points: tuple[TrajectoryPoint, ...]
    kind: str  # "arm", "cartesian", "base", ...
    task_path: str | None  # the task running when it was executed
    time: float  # [s] since the epoch (wall clock) when it was reported, its motion's end
    start: float  # [s] from the run's start on the replay clock (traces/replay_clock.py)
    allowed_contacts: tuple[ContactAllowance, ...] = ()  # beyond the description's
    carried: tuple[CarriedJoint, ...] = ()  # other objects' joints it moved along

    @property
    def duration(self) -> float:
        """Time from its first to its last point [s]."""
        return self.points[-1].time_from_start if self.points else 0.0

    @property
    def end(self) -> float:
        """When it ended [s] from the run's start, on the replay clock."""
        return self.start + self.duration

    def trajectory(self) -> JointTrajectory:
        """The trajectory as the motion layer made it."""
        return JointTrajectory(
            self.robot, self.joint_names, self.points, self.kind, self.allowed_contacts,
            self.carried,
        )  # fmt: skip


def trajectory_row(
    run_id: int, task_id: int | None, sequence: int, time: float, trajectory: JointTrajectory
) -> dict[str, object]:
    """The ``trajectories`` row of ``trajectory`` (Core executemany on the tracer's hot path)."""
    points = trajectory.points
    return {
        "run_id": run_id,
        "task_id": task_id,
        "sequence": sequence,
        "time": time,
        "robot": trajectory.robot,
        "kind": trajectory.kind,
        "joint_names": json.dumps(list(trajectory.joint_names)),
        "times": _pack([p.time_from_start for p in points]),
        "positions": _pack([p.positions for p in points]),
        "velocities": _pack([p.velocities for p in points]),
        "accelerations": _pack([p.accelerations for p in points]),
        "allowed_contacts": _allowances_text(trajectory.allowed_contacts),
        "carried": _carried_text(trajectory.carried),
    }


def run_trajectories(
    db: TraceDatabase | str | Path, run: int, skip_damaged: bool = False
) -> list[StoredTrajectory]:
    """The trajectories run ``run`` executed, in execution order.

    ``db`` is an open database or the path of one (opened for this query only).
    ``skip_damaged``: leave out rows that do not decode, each with a
    :class:`DamagedTrajectoryWarning` naming it (a replay shows the rest).

    Raises:
        UnknownRun: the database has no run ``run`` (the message lists those it has).
        DamagedTrajectory: a row does not decode (unless ``skip_damaged``); it names the
            run and the trajectory.
    """
    if not isinstance(db, TraceDatabase):
        with TraceDatabase(db, create=False) as opened:
            return run_trajectories(opened, run, skip_damaged)
    run_start = require_run(db, run).start
    query = (
        select(TrajectoryRow, TaskRow.path)
        .outerjoin(TaskRow, TaskRow.id == TrajectoryRow.task_id)
        .where(TrajectoryRow.run_id == run)
        .order_by(TrajectoryRow.sequence)
    )
    with db.read() as session:
        rows = [(row, path) for row, path in session.execute(query)]
    loaded = [t for t in (_checked(row, path, skip_damaged) for row, path in rows) if t]
    states = [time for _, time, _ in world_state_times(db, run)]
    starts = replay_starts(run_start, [(t.time, t.duration) for t in loaded], states)
    return [replace(t, start=start - run_start) for t, start in zip(loaded, starts, strict=True)]


def replay_clock(db: TraceDatabase, run: int) -> ReplayClock:
    """The replay clock of run ``run``: its wall times stretched to hold its trajectories."""
    states = [time for _, time, _ in world_state_times(db, run)]
    reported = [(t.time, t.duration) for t in run_trajectories(db, run)]
    return ReplayClock(require_run(db, run).start, reported, states)


def _checked(row: TrajectoryRow, path: str | None, skip: bool) -> StoredTrajectory | None:
    """The row's trajectory; None for a damaged row when ``skip`` (with a warning)."""
    try:
        return _loaded(row, path)
    except DamagedTrajectory as damaged:
        if not skip:
            raise
        warnings.warn(f"skipped: {damaged}", DamagedTrajectoryWarning, stacklevel=4)
        return None


def _loaded(row: TrajectoryRow, path: str | None) -> StoredTrajectory:
    """The row as a trajectory, after checking everything it decodes to.

    Raises:
        DamagedTrajectory: naming the run, the trajectory and what is wrong with the row.
    """
    try:
        names, times, columns = _decoded(row)
        allowed = _allowances(row.allowed_contacts)
        carried = _carried(row.carried)
    except (ValueError, TypeError, KeyError) as err:  # json.JSONDecodeError is a ValueError
        raise DamagedTrajectory(row.run_id, row.sequence, str(err)) from err
    points = tuple(
        TrajectoryPoint(
            tuple(columns[0][i].tolist()),
            tuple(columns[1][i].tolist()),
            tuple(columns[2][i].tolist()),
            float(times[i]),
        )
        for i in range(len(times))
    )
    return StoredTrajectory(
        index=row.sequence,
        robot=row.robot,
        joint_names=names,
        points=points,
        kind=row.kind,
        task_path=path,
        time=row.time,
        start=0.0,
        allowed_contacts=allowed,
        carried=carried,
    )


def _decoded(
    row: TrajectoryRow,
) -> tuple[tuple[str, ...], NDArray[np.float64], list[NDArray[np.float64]]]:
    """Joint names, times and (positions, velocities, accelerations) of a row, checked:
    whole float64 blobs of one row per point, finite numbers, times never going back."""
    names = json.loads(row.joint_names)
    if not isinstance(names, list) or not all(isinstance(n, str) for n in names):
        raise TraceArgumentError(f"joint names {row.joint_names!r} are not a JSON list of names")
    times = _floats(row.times, "times")
    shape = (len(times), len(names))
    columns = [
        _rows(_floats(data, what), shape, what, empty_ok=what != "positions")
        for data, what in (
            (row.positions, "positions"),
            (row.velocities, "velocities"),
            (row.accelerations, "accelerations"),
        )
    ]
    if len(times) and not (np.diff(times) >= 0.0).all():
        raise TraceArgumentError("its times run backwards")
    return tuple(names), times, columns


def _floats(data: bytes, what: str) -> NDArray[np.float64]:
    """A blob of float64s, all finite."""
    if len(data) % 8:
        raise TraceArgumentError(f"its {what} blob of {len(data)} bytes is cut short")
    values = np.frombuffer(data, dtype="<f8")
    if not np.isfinite(values).all():
        raise TraceArgumentError(f"its {what} hold numbers that are not finite")
    return values


def _allowances_text(allowances: tuple[ContactAllowance, ...]) -> str | None:
    """JSON ``[[robot side, other, depth], ...]``; None (NULL) when there are none."""
    if not allowances:
        return None
    return json.dumps([[a.robot_side, a.other, a.depth] for a in allowances])


def _allowances(text: str | None) -> tuple[ContactAllowance, ...]:
    """The allowances of a row; NULL (none, or a file written before version 6): none."""
    if not text:
        return ()
    return tuple(ContactAllowance(side, other, depth) for side, other, depth in json.loads(text))


def _carried_text(carried: tuple[CarriedJoint, ...]) -> str | None:
    """JSON ``[[object, joint, start, end], ...]``, with ``link, [from, to]`` after ``end``
    for a joint moved along a link's line; None (NULL) when there are none."""
    if not carried:
        return None
    return json.dumps([_carried_row(c) for c in carried])


def _carried_row(c: CarriedJoint) -> list[object]:
    row: list[object] = [c.obj, c.joint, c.start, c.end]
    if c.line is not None:
        row += [c.link, [list(c.line[0]), list(c.line[1])]]
    return row


def _carried(text: str | None) -> tuple[CarriedJoint, ...]:
    """The carried joints of a row; NULL (none, or a file before version 7): none. A row of
    four (a file before the line was kept) moves by time."""
    if not text:
        return ()
    found = []
    for obj, joint, start, end, *along in json.loads(text):
        if along:
            link, (begin, finish) = along
            found.append(CarriedJoint(obj, joint, start, end, link, (tuple(begin), tuple(finish))))
        else:
            found.append(CarriedJoint(obj, joint, start, end))
    return tuple(found)


def _pack(values: ArrayLike) -> bytes:
    """Raw little-endian float64: zlib would save a quarter and double the tracer's cost."""
    return np.ascontiguousarray(values, dtype="<f8").tobytes()


def _rows(
    values: NDArray[np.float64], shape: tuple[int, int], what: str, empty_ok: bool
) -> NDArray[np.float64]:
    """Rows of one point each; velocities a driver left empty come back empty."""
    if values.size != shape[0] * shape[1] and not (empty_ok and values.size == 0):
        raise TraceArgumentError(
            f"its {what} hold {values.size} numbers, not {shape[0]} x {shape[1]}"
        )
    return values.reshape(shape[0], -1) if shape[0] else values.reshape(shape)

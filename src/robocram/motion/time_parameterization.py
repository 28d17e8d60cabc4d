"""Time a collision-checked joint-space polyline without leaving it.

The path's waypoints were checked densely along straight lines between them, so the
timed trajectory must stay on those lines: every sampled point lies on the polyline
(within 1e-6). Two kinds of corner decide how:

- a **sharp corner** (the direction turns by more than :data:`SMOOTH_TURN`) is where the
  robot stops; the single segments between sharp corners are timed jerk-limited by ruckig
  (phase-synchronised, so straight; checked) from rest to rest, the time-optimal straight
  move under every joint's velocity, acceleration and jerk limit;
- a **smooth corner** (a dense path, e.g. a Cartesian line as 15 waypoints 2 cm
  apart) is passed without stopping: the run of segments between sharp corners is timed
  along its arc length (:mod:`robocram.motion.arc_length_profile`) with per-segment
  velocity and acceleration caps and corner speeds that keep each joint's velocity step at
  a corner within ``acceleration * period``. Merging nearly collinear segments into one
  ruckig move instead would leave the polyline, so it is not done.

The trajectory is sampled every ``period`` and at every waypoint.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from robocram.motion.arc_length_profile import ArcRun, IntArray, arc_length_run
from robocram.motion.errors import MotionError
from robocram.motion.joint_limits import JointLimits
from robocram.motion.joint_trajectory import FloatArray, JointTrajectory, TrajectoryPoint, still
from robocram.motion.straight_segment import StraightSegment, straight_segment

SMOOTH_TURN = 0.2  # [rad] turns of the path's direction up to this are passed without stopping
SAME_POINT = 1e-12  # [rad | m] consecutive waypoints closer than this are one waypoint
SAME_TIME = 1e-9  # [s] a periodic sample this close to a waypoint's time is dropped
LIMIT_SLACK = 1e-9  # [rad | m] a waypoint this far outside a position limit still counts

State = tuple[FloatArray, FloatArray, FloatArray]


@dataclass(frozen=True)
class _Piece:
    """One segment of the timed path, from waypoint to waypoint, on the global clock."""

    t0: float  # [s]
    t1: float  # [s]
    motion: StraightSegment | ArcRun  # the timed motion it is (a segment of)
    segment: int  # which segment of an ArcRun; 0 for a StraightSegment
    offset: float  # [s] global time of the motion's own time 0


def time_parameterize(
    robot: str,
    joint_names: Sequence[str],
    path: Sequence[Sequence[float]] | np.ndarray,
    limits: Sequence[JointLimits],
    *,
    kind: str = "arm",
    period: float = 0.05,
) -> JointTrajectory:
    """Time ``path`` (waypoints of ``joint_names``) under ``limits``, exactly on the polyline.

    Args:
        robot: The robot the trajectory is for.
        joint_names: The joints, in the order of each waypoint's values.
        path: Waypoints [rad | m], already collision-checked along straight lines.
        limits: One :class:`JointLimits` per joint, same order (``joint_limits(desc, names)``).
        kind: What made it (``arm``, ``base``), kept in the trajectory.
        period: Sampling period [s]; also the corner blend time of dense paths.

    Raises:
        MotionError: widths that do not match, non-finite values, a waypoint outside a
            position limit, a non-positive period or limit (each named).
    """
    names = tuple(joint_names)
    points = _checked_path(names, path, limits, period)
    distinct = [points[0]]
    for point in points[1:]:
        if _length(point - distinct[-1]) > SAME_POINT:
            distinct.append(point)
    if len(distinct) == 1:
        return JointTrajectory(robot, names, still(robot, names, distinct[0].tolist()).points, kind)
    pieces = _timed_pieces(distinct, limits, period)
    return JointTrajectory(robot, names, _sampled(distinct, pieces, period), kind)


def _timed_pieces(
    waypoints: list[FloatArray], limits: Sequence[JointLimits], period: float
) -> list[_Piece]:
    """Split at sharp corners and time each run, runs one after another from rest."""
    pieces: list[_Piece] = []
    clock = 0.0
    for first, last in _runs(waypoints):
        if last - first == 1:
            segment = straight_segment(waypoints[first], waypoints[last], limits)
            pieces.append(_Piece(clock, clock + segment.duration, segment, 0, clock))
        else:
            run = arc_length_run(waypoints[first : last + 1], limits, period)
            spans = zip(run.t_starts.tolist(), run.t_ends.tolist(), strict=True)
            for k, (t_start, t_end) in enumerate(spans):
                pieces.append(_Piece(clock + t_start, clock + t_end, run, k, clock))
        clock = pieces[-1].t1
    return pieces


def _runs(waypoints: list[FloatArray]) -> list[tuple[int, int]]:
    """Index ranges ``(first, last)`` of waypoints between sharp corners."""
    runs = []
    first = 0
    for k in range(1, len(waypoints) - 1):
        before = waypoints[k] - waypoints[k - 1]
        after = waypoints[k + 1] - waypoints[k]
        cos = float(before.dot(after)) / (_length(before) * _length(after))
        if math.acos(min(max(cos, -1.0), 1.0)) > SMOOTH_TURN:
            runs.append((first, k))
            first = k
    runs.append((first, len(waypoints) - 1))
    return runs


def _length(vector: FloatArray) -> float:
    """``np.linalg.norm`` of a vector, bit for bit (the root of its dot product), without
    the wrapper that costs two microseconds a call."""
    return math.sqrt(float(vector.dot(vector)))


def _sampled(
    waypoints: list[FloatArray], pieces: list[_Piece], period: float
) -> tuple[TrajectoryPoint, ...]:
    """Points every ``period`` and at every waypoint; at a waypoint, its exact position
    with the mean of the motions arriving and leaving (at rest at both ends).

    A time between waypoints belongs to the first piece that does not end before it.
    """
    stops = [pieces[0].t0] + [p.t1 for p in pieces]
    times = _sample_times(stops, period)
    stop_index = {t: k for k, t in reversed(list(enumerate(stops)))}
    at_stop = [stop_index.get(t, -1) for t in times]  # the waypoint there, or -1
    between = [i for i, k in enumerate(at_stop) if k < 0]
    clock = np.array([times[i] for i in between])
    owner = np.searchsorted(np.array(stops[1:]) + SAME_TIME, clock, side="left")
    corners = np.arange(1, len(pieces))  # waypoint k joins piece k - 1 and piece k
    asked = _states(
        pieces,
        np.concatenate([np.minimum(owner, len(pieces) - 1), corners - 1, corners]),
        np.array([*clock.tolist(), *stops[1:-1], *(pieces[k].t0 for k in corners)]),
        len(waypoints[0]),
    )
    rows = [np.zeros((len(times), len(waypoints[0]))) for _ in range(3)]
    for row, values in zip(rows, asked, strict=True):
        row[between] = values[: len(clock)]
    stopped = [i for i, k in enumerate(at_stop) if k >= 0]
    rows[0][stopped] = np.array(waypoints)[[at_stop[i] for i in stopped]]
    inner = [i for i in stopped if 0 < at_stop[i] < len(waypoints) - 1]
    arriving = len(clock) - 1 + np.array([at_stop[i] for i in inner], dtype=np.intp)
    leaving = arriving + len(corners)  # the rows ``asked`` for waypoint k's two pieces
    for row, values in zip(rows[1:], asked[1:], strict=True):
        row[inner] = 0.5 * (values[arriving] + values[leaving])
    positions, velocities, accelerations = (map(tuple, row.tolist()) for row in rows)
    return tuple(map(TrajectoryPoint, positions, velocities, accelerations, map(float, times)))


def _sample_times(stops: list[float], period: float) -> list[float]:
    """Every ``period`` [s] and every stop, sorted; a tick this close to a stop is dropped."""
    ticks = np.arange(int(math.floor(stops[-1] / period)) + 1) * period
    where = np.clip(np.searchsorted(stops, ticks), 1, len(stops) - 1)
    gap = np.minimum(
        np.abs(ticks - np.take(stops, where)), np.abs(ticks - np.take(stops, where - 1))
    )
    return sorted([*ticks[gap > SAME_TIME].tolist(), *stops])


def _states(pieces: list[_Piece], owners: IntArray, times: FloatArray, width: int) -> State:
    """Positions, velocities, accelerations (one row each) of piece ``owners[i]`` at global
    time ``times[i]`` [s]; each motion computes all of its rows at once."""
    groups: dict[int, list[int]] = {}  # id of a motion -> its pieces
    for k, piece in enumerate(pieces):
        groups.setdefault(id(piece.motion), []).append(k)
    group_of = np.zeros(len(pieces), dtype=np.intp)
    for g, members in enumerate(groups.values()):
        group_of[members] = g
    group = group_of[owners]
    segment = np.array([p.segment for p in pieces])[owners]
    local = times - np.array([p.offset for p in pieces])[owners]
    out = (
        np.zeros((len(times), width)),
        np.zeros((len(times), width)),
        np.zeros((len(times), width)),
    )
    for g, members in enumerate(groups.values()):
        mine = np.flatnonzero(group == g)
        motion = pieces[members[0]].motion
        if not len(mine):
            continue
        if isinstance(motion, ArcRun):
            values = motion.states(segment[mine], local[mine])
        else:
            values = motion.states(local[mine])
        for row, value in zip(out, values, strict=True):
            row[mine] = value
    return out


def _checked_path(
    names: tuple[str, ...],
    path: Sequence[Sequence[float]] | np.ndarray,
    limits: Sequence[JointLimits],
    period: float,
) -> list[FloatArray]:
    """The waypoints as arrays, after checking every input the timing relies on."""
    if not (math.isfinite(period) and period > 0.0):
        raise MotionError(f"sampling period must be a positive number of seconds, got {period}")
    if len(limits) != len(names) or any(
        lim.name != n for lim, n in zip(limits, names, strict=False)
    ):
        raise MotionError(
            f"limits are for {[lim.name for lim in limits]}, the path's joints are "
            f"{list(names)}; pass joint_limits(desc, joint_names)"
        )
    for lim in limits:
        rates = (lim.velocity, lim.acceleration, lim.jerk)
        if not all(math.isfinite(v) and v > 0.0 for v in rates):
            raise MotionError(
                f"joint {lim.name!r} has velocity/acceleration/jerk limits {rates}; "
                "each must be positive and finite"
            )
    if len(path) == 0:
        raise MotionError("the path has no waypoints; give at least the start")
    fast = _within_limits(path, len(names), limits)
    if fast is not None:
        return fast
    points = []
    for i, raw in enumerate(path):
        point = np.asarray(raw, dtype=float)
        if point.shape != (len(names),):
            raise MotionError(
                f"waypoint {i} has shape {point.shape}, expected ({len(names)},) for {names}"
            )
        for name, value, lim in zip(names, point, limits, strict=True):
            if not math.isfinite(value):
                raise MotionError(f"waypoint {i} has {value} for joint {name!r}")
            if not lim.lower - LIMIT_SLACK <= value <= lim.upper + LIMIT_SLACK:
                raise MotionError(
                    f"waypoint {i} puts joint {name!r} at {value}, outside its limits "
                    f"[{lim.lower}, {lim.upper}]; clamp the path or fix the goal"
                )
        points.append(point)
    return points


def _within_limits(
    path: Sequence[Sequence[float]] | np.ndarray, width: int, limits: Sequence[JointLimits]
) -> list[FloatArray] | None:
    """The waypoints as rows of one array when all are fine (the same tests as the checks
    per value, all at once); None when one is not, for those checks to name it."""
    try:
        table = np.array(path, dtype=float)
    except (TypeError, ValueError):  # ragged, or not numbers
        return None
    if table.ndim != 2 or table.shape[1] != width or not np.isfinite(table).all():
        return None
    lower = np.array([lim.lower for lim in limits]) - LIMIT_SLACK
    upper = np.array([lim.upper for lim in limits]) + LIMIT_SLACK
    if not ((lower <= table) & (table <= upper)).all():
        return None
    return list(table)

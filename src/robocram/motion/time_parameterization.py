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
from robocram.motion.joint_trajectory import FloatArray, JointTrajectory, PointTable, still
from robocram.motion.straight_segment import StraightSegment, straight_segment

SMOOTH_TURN = 0.2  # [rad] turns of the path's direction up to this are passed without stopping
SAME_POINT = 1e-12  # [rad | m] consecutive waypoints closer than this are one waypoint
SAME_TIME = 1e-9  # [s] a periodic sample this close to a waypoint's time is dropped
LIMIT_SLACK = 1e-9  # [rad | m] a waypoint this far outside a position limit still counts

State = tuple[FloatArray, FloatArray, FloatArray]


@dataclass(frozen=True)
class _Timeline:
    """The timed path on the global clock: its motions one after another, and its pieces
    (one per segment, from waypoint ``k`` to ``k + 1``, numbered along the path)."""

    motions: list[StraightSegment | ArcRun]
    firsts: IntArray  # (motions,) the first piece of each motion
    offsets: FloatArray  # (motions,) [s] global time of each motion's own time 0
    stops: FloatArray  # (pieces + 1,) [s] when the path passes each waypoint


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
    timeline = _timed_path(distinct, limits, period)
    return JointTrajectory(robot, names, _sampled(np.array(distinct), timeline, period), kind)


def _timed_path(
    waypoints: list[FloatArray], limits: Sequence[JointLimits], period: float
) -> _Timeline:
    """Split at sharp corners and time each run, runs one after another from rest."""
    motions: list[StraightSegment | ArcRun] = []
    firsts, offsets, ends = [], [], [np.zeros(1)]
    clock = 0.0
    for first, last in _runs(waypoints):
        motion: StraightSegment | ArcRun
        if last - first == 1:
            motion = straight_segment(waypoints[first], waypoints[last], limits)
            piece_ends = np.array([motion.duration])
        else:
            motion = arc_length_run(waypoints[first : last + 1], limits, period)
            piece_ends = motion.t_ends
        motions.append(motion)
        firsts.append(first)
        offsets.append(clock)
        ends.append(clock + piece_ends)
        clock = float(ends[-1][-1])
    return _Timeline(
        motions, np.array(firsts, dtype=np.intp), np.array(offsets), np.concatenate(ends)
    )


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


def _sampled(waypoints: FloatArray, timeline: _Timeline, period: float) -> PointTable:
    """Points every ``period`` and at every waypoint; at a waypoint, its exact position
    with the mean of the motions arriving and leaving (at rest at both ends).

    A time between waypoints belongs to the first piece that does not end before it.
    """
    stops = timeline.stops
    ticks = _ticks(stops, period)
    count, pieces, width = len(ticks) + len(stops), len(stops) - 1, waypoints.shape[1]
    tick_rows = np.arange(len(ticks)) + stops.searchsorted(ticks)  # none is a stop
    stop_rows = np.arange(len(stops)) + ticks.searchsorted(stops)
    owner = (stops[1:] + SAME_TIME).searchsorted(ticks, side="left")
    corners = np.arange(1, pieces)  # waypoint k joins piece k - 1 and piece k
    asked = _states(
        timeline,
        np.concatenate([np.minimum(owner, pieces - 1), corners - 1, corners]),
        np.concatenate([ticks, stops[1:-1], stops[1:-1]]),  # a piece starts where the last ends
        width,
    )
    times = np.empty(count)
    times[tick_rows] = ticks
    times[stop_rows] = stops
    positions = np.empty((count, width))
    positions[tick_rows] = asked[0][: len(ticks)]
    positions[stop_rows] = waypoints
    rates = np.zeros((count, width)), np.zeros((count, width))
    arriving = slice(len(ticks), len(ticks) + len(corners))  # rows asked for the corners
    leaving = slice(len(ticks) + len(corners), None)
    for row, values in zip(rates, asked[1:], strict=True):
        row[tick_rows] = values[: len(ticks)]
        row[stop_rows[1:-1]] = 0.5 * (values[arriving] + values[leaving])
    return PointTable(positions, *rates, times)


def _ticks(stops: FloatArray, period: float) -> FloatArray:
    """Every ``period`` [s] up to the last stop, but for those this close to a stop."""
    ticks = np.arange(math.floor(float(stops[-1]) / period) + 1, dtype=float) * period
    where = np.minimum(np.maximum(stops.searchsorted(ticks), 1), len(stops) - 1)
    gap = np.minimum(np.abs(ticks - stops[where]), np.abs(ticks - stops[where - 1]))
    return ticks[gap > SAME_TIME]


def _states(timeline: _Timeline, owners: IntArray, times: FloatArray, width: int) -> State:
    """Positions, velocities, accelerations (one row each) of piece ``owners[i]`` at global
    time ``times[i]`` [s]; each motion computes all of its rows at once."""
    if len(timeline.motions) == 1:  # most paths: one straight move or one smooth run
        motion = timeline.motions[0]
        local = times - timeline.offsets[0]
        return motion.states(owners, local) if isinstance(motion, ArcRun) else motion.states(local)
    group = timeline.firsts.searchsorted(owners, side="right") - 1
    segment = owners - timeline.firsts[group]
    local = times - timeline.offsets[group]
    out = (
        np.zeros((len(times), width)),
        np.zeros((len(times), width)),
        np.zeros((len(times), width)),
    )
    for g, motion in enumerate(timeline.motions):
        mine = np.flatnonzero(group == g)
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
    bounds = np.array(
        [(lim.lower, lim.upper, lim.velocity, lim.acceleration, lim.jerk) for lim in limits],
        dtype=float,
    ).reshape(len(limits), 5)
    rates = bounds[:, 2:]
    if not ((rates > 0.0) & (rates < math.inf)).all():  # positive and finite, NaN neither
        for lim in limits:
            given = (lim.velocity, lim.acceleration, lim.jerk)
            if not all(math.isfinite(v) and v > 0.0 for v in given):
                raise MotionError(
                    f"joint {lim.name!r} has velocity/acceleration/jerk limits {given}; "
                    "each must be positive and finite"
                )
    if len(path) == 0:
        raise MotionError("the path has no waypoints; give at least the start")
    fast = _within_limits(path, len(names), bounds)
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
    path: Sequence[Sequence[float]] | np.ndarray, width: int, bounds: FloatArray
) -> list[FloatArray] | None:
    """The waypoints as rows of one array when all are fine (the same tests as the checks
    per value, all at once); None when one is not, for those checks to name it.
    ``bounds`` holds a row per joint, its lower and upper limits first."""
    try:
        table = np.array(path, dtype=float)
    except (TypeError, ValueError):  # ragged, or not numbers
        return None
    if table.ndim != 2 or table.shape[1] != width:
        return None
    lower = bounds[:, 0] - LIMIT_SLACK
    upper = bounds[:, 1] + LIMIT_SLACK
    if not ((lower <= table) & (table <= upper) & np.isfinite(table)).all():
        return None
    return list(table)

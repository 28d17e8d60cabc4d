"""Time a collision-checked joint-space polyline, leaving it only on checked blends.

The path's waypoints were checked densely along straight lines between them, so the
timed trajectory stays on those lines: every sampled point lies on the polyline (within
1e-6). A joint's velocity must be continuous and its acceleration and jerk bounded, and on
a polyline that means **rest at every corner**: passing a corner of turn ``du`` at path
speed ``s_dot`` changes the joint velocities at once by ``du * s_dot``, an unbounded
acceleration whatever the speed cap (the profile this replaced did so, up to 20x the
acceleration limit and 1,000x the jerk limit measured 2 ms apart on a tool line). So each
segment is timed jerk-limited by ruckig from rest to rest (phase-synchronised, so
straight; checked), the time-optimal straight move under every joint's velocity,
acceleration and jerk limit; waypoints within :data:`COLLINEAR` of the line through their
neighbours are passed without stopping (the geometry is the same line).

Blending a corner leaves the checked polyline, so it needs a check of the new geometry:
a caller that has the path's checker passes ``corner_radii`` of blends walked free on it
(:func:`~robocram.motion.corner_blend.blend_radii`, as tool lines do); a run of such
corners is passed without stopping (:mod:`robocram.motion.corner_blend`).

The trajectory is sampled every ``period``, at every rest and at every jerk switch
(:func:`sampled_trajectory`, shared with :mod:`robocram.motion.car_timing` and the
blended runs of :mod:`robocram.motion.corner_blend`): between two samples a straight
piece is one cubic polynomial, which a controller's quintic interpolation reproduces.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Protocol

import numpy as np

from robocram.motion.corner_blend import blended_run
from robocram.motion.errors import MotionError, MotionInputError
from robocram.motion.joint_limits import JointLimits
from robocram.motion.joint_trajectory import FloatArray, JointTrajectory, PointTable, still
from robocram.motion.straight_segment import straight_segment
from robocram.robots.limit_check import MIN_RATE_LIMIT

COLLINEAR = 1e-9  # [rad | m] a waypoint this close to its neighbours' line is no corner
SAME_POINT = 1e-12  # [rad | m] consecutive waypoints closer than this are one waypoint
SAME_TIME = 1e-9  # [s] a periodic sample this close to a waypoint's time is dropped
BREAK_GAP = 1e-6  # [s] a jerk switch this close to another sample gets no sample
LIMIT_SLACK = 1e-9  # [rad | m] a waypoint this far outside a position limit still counts
# Sizes that grow with the input are bounded (each named in its error): ruckig times each
# corner (10^5 sharp waypoints took over 120 s), and the samples are allocated at once
# (a period of 1e-9 s asked for 7.45 GiB). Planned paths have tens of waypoints, and a
# 0.05 s period gives an hour of motion in 72,000 points.
MAX_WAYPOINTS = 10_000
MAX_RATE_LIMIT = 1e9  # [/s, /s^2, /s^3] ruckig fails on 1e300 (and on 1e-300: MIN_RATE_LIMIT)
MAX_TRAJECTORY_POINTS = 200_000

State = tuple[FloatArray, FloatArray, FloatArray]


class TimedPiece(Protocol):
    """A piece of a trajectory from rest to rest: its duration and its states."""

    @property
    def duration(self) -> float: ...

    def states(self, times: FloatArray) -> State: ...

    def breaks(self) -> FloatArray: ...


def time_parameterize(
    robot_name: str,
    joint_names: Sequence[str],
    path: Sequence[Sequence[float]] | np.ndarray,
    limits: Sequence[JointLimits],
    *,
    kind: str = "arm",
    period: float = 0.05,
    corner_radii: Sequence[float] | None = None,
) -> JointTrajectory:
    """Time ``path`` (waypoints of ``joint_names``) under ``limits``, on the polyline.

    Args:
        robot_name: The robot the trajectory is for (its name, kept in the trajectory).
        joint_names: The joints, in the order of each waypoint's values.
        path: Waypoints [rad | m], already collision-checked along straight lines.
        limits: One :class:`JointLimits` per joint, same order (``joint_limits(desc, names)``).
        kind: What made it (``arm``, ``base``), kept in the trajectory.
        period: Sampling period [s].
        corner_radii: Per inner waypoint, the radius of a blend checked free
            (:func:`~robocram.motion.corner_blend.blend_radii`; 0: rest there). None:
            rest at every corner, exactly on the polyline.

    Raises:
        MotionError: widths that do not match, non-finite values, a waypoint outside a
            position limit, a non-positive period or limit (each named).
        MotionInputError: more than :data:`MAX_WAYPOINTS` waypoints, or more than
            :data:`MAX_TRAJECTORY_POINTS` samples at this period.
    """
    names = tuple(joint_names)
    if len(path) > MAX_WAYPOINTS:
        raise MotionInputError(
            f"the path has {len(path)} waypoints, more than the bound of {MAX_WAYPOINTS} "
            "(MAX_WAYPOINTS); simplify it or time it in parts",
            value=len(path),
            bound=MAX_WAYPOINTS,
        )
    points = checked_path(names, path, limits, period)
    distinct = [points[0]]
    for point in points[1:]:
        if _length(point - distinct[-1]) > SAME_POINT:
            distinct.append(point)
    if len(distinct) == 1:
        return JointTrajectory(
            robot_name, names, still(robot_name, names, distinct[0].tolist()).points, kind
        )
    if corner_radii is not None and len(distinct) == len(points) > 2:
        if len(corner_radii) != len(points) - 2:
            raise MotionError(
                f"{len(corner_radii)} corner radii for {len(points) - 2} inner waypoints"
            )
        stops, pieces = _blended(np.array(distinct), np.array(corner_radii, dtype=float), limits)
        return sampled_trajectory(robot_name, names, stops, pieces, period, kind)
    corners = _corners(distinct)
    straight = [straight_segment(a, b, limits) for a, b in zip(corners, corners[1:], strict=False)]
    return sampled_trajectory(robot_name, names, np.array(corners), straight, period, kind)


def _blended(
    points: FloatArray, radii: FloatArray, limits: Sequence[JointLimits]
) -> tuple[FloatArray, list[TimedPiece]]:
    """Runs between the corners of radius 0, each blended through its inner corners (or,
    when that is no faster, resting at each): the stops and the pieces between them."""
    rests = [0, *(np.flatnonzero(radii <= 0.0) + 1).tolist(), len(points) - 1]
    stops = [points[0]]
    pieces: list[TimedPiece] = []
    for first, last in zip(rests[:-1], rests[1:], strict=True):
        run = None
        if last - first > 1:
            run = blended_run(points[first : last + 1], radii[first : last - 1], limits)
        if run is not None:
            pieces.append(run)
            stops.append(points[last])
            continue
        for k in range(first, last):
            pieces.append(straight_segment(points[k], points[k + 1], limits))
            stops.append(points[k + 1])
    return np.array(stops), pieces


def _corners(waypoints: list[FloatArray]) -> list[FloatArray]:
    """The waypoints but those within :data:`COLLINEAR` of the segment joining their
    neighbours kept (they lie on it, so the robot passes them without stopping)."""
    kept = [waypoints[0]]
    for k in range(1, len(waypoints) - 1):
        a, b, c = kept[-1], waypoints[k], waypoints[k + 1]
        chord = c - a
        span = float(chord.dot(chord))
        if span == 0.0:  # out and back: b is a turning point
            kept.append(b)
            continue
        along = float((b - a).dot(chord)) / span
        if not 0.0 < along < 1.0 or _length(b - a - along * chord) > COLLINEAR:
            kept.append(b)
    kept.append(waypoints[-1])
    return kept


def _length(vector: FloatArray) -> float:
    """``np.linalg.norm`` of a vector, bit for bit (the root of its dot product), without
    the wrapper that costs two microseconds a call."""
    return math.sqrt(float(vector.dot(vector)))


def sampled_trajectory(
    robot_name: str,
    names: tuple[str, ...],
    stops: FloatArray,
    pieces: Sequence[TimedPiece],
    period: float,
    kind: str,
) -> JointTrajectory:
    """The pieces one after another (piece ``k`` from rest at ``stops[k]`` to rest at
    ``stops[k + 1]``), sampled every ``period`` [s] and at every stop (its exact position,
    at rest).

    Raises:
        MotionInputError: more than :data:`MAX_TRAJECTORY_POINTS` samples, before any is made.
    """
    ends = np.cumsum([0.0] + [piece.duration for piece in pieces])
    _check_sample_count(float(ends[-1]), period, len(ends))
    ticks = _with_breaks(_ticks(ends, period), ends, pieces)
    count, width = len(ticks) + len(ends), stops.shape[1]
    tick_rows = np.arange(len(ticks)) + ends.searchsorted(ticks)  # none is a stop
    stop_rows = np.arange(len(ends)) + ticks.searchsorted(ends)
    owner = np.minimum((ends[1:] + SAME_TIME).searchsorted(ticks, side="left"), len(pieces) - 1)
    times = np.empty(count)
    times[tick_rows] = ticks
    times[stop_rows] = ends
    positions = np.empty((count, width))
    positions[stop_rows] = stops
    rates = np.zeros((count, width)), np.zeros((count, width))
    for k, piece in enumerate(pieces):
        mine = np.flatnonzero(owner == k)
        if not len(mine):
            continue
        values = piece.states(ticks[mine] - ends[k])
        rows = tick_rows[mine]
        positions[rows] = values[0]
        rates[0][rows] = values[1]
        rates[1][rows] = values[2]
    return JointTrajectory(robot_name, names, PointTable(positions, *rates, times), kind)


def _check_sample_count(duration: float, period: float, stops: int) -> None:
    """Refuse a trajectory of more than :data:`MAX_TRAJECTORY_POINTS` samples (its
    periodic samples and its stops; the few jerk switches of each piece come on top)."""
    count = duration / period + stops
    if not count <= MAX_TRAJECTORY_POINTS:
        raise MotionInputError(
            f"{duration:.3g} s sampled every {period:g} s is {count:.3g} trajectory points, "
            f"more than the bound of {MAX_TRAJECTORY_POINTS} (MAX_TRAJECTORY_POINTS); "
            "sample less often (a larger period) or move less far",
            value=count,
            bound=MAX_TRAJECTORY_POINTS,
        )


def _with_breaks(ticks: FloatArray, ends: FloatArray, pieces: Sequence[TimedPiece]) -> FloatArray:
    """``ticks`` and the times where a piece's jerk changes, but for those within
    :data:`BREAK_GAP` of a tick, a stop or another: between two samples the motion is
    then one polynomial (on a straight piece), which a controller's quintic
    interpolation of the samples reproduces."""
    pairs = zip(pieces, ends, strict=False)
    breaks = np.concatenate([piece.breaks() + end for piece, end in pairs])
    if not len(breaks):
        return ticks
    taken = np.sort(np.concatenate([ticks, ends]))
    kept: list[float] = []
    for t in np.sort(breaks).tolist():
        i = int(taken.searchsorted(t))
        near = min(abs(t - taken[max(i - 1, 0)]), abs(t - taken[min(i, len(taken) - 1)]))
        if near > BREAK_GAP and (not kept or t - kept[-1] > BREAK_GAP):
            kept.append(t)
    return np.sort(np.concatenate([ticks, kept]))


def _ticks(stops: FloatArray, period: float) -> FloatArray:
    """Every ``period`` [s] up to the last stop, but for those this close to a stop."""
    ticks = np.arange(math.floor(float(stops[-1]) / period) + 1, dtype=float) * period
    where = np.minimum(np.maximum(stops.searchsorted(ticks), 1), len(stops) - 1)
    gap = np.minimum(np.abs(ticks - stops[where]), np.abs(ticks - stops[where - 1]))
    return ticks[gap > SAME_TIME]


def checked_path(
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
    if not ((rates >= MIN_RATE_LIMIT) & (rates <= MAX_RATE_LIMIT)).all():  # NaN neither
        for lim in limits:
            given = (lim.velocity, lim.acceleration, lim.jerk)
            if not all(MIN_RATE_LIMIT <= v <= MAX_RATE_LIMIT for v in given):
                raise MotionInputError(
                    f"joint {lim.name!r} has velocity/acceleration/jerk limits {given}; "
                    f"each must be positive and finite, from {MIN_RATE_LIMIT:g} (MIN_RATE_LIMIT) "
                    f"to {MAX_RATE_LIMIT:g} (MAX_RATE_LIMIT): ruckig cannot time the others",
                    joint=lim.name,
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

"""Time a collision-checked joint-space polyline without leaving it.

The path's waypoints were checked densely along straight lines between them, so the
timed trajectory must stay on those lines: every sampled point lies on the polyline
(within 1e-6). Two kinds of corner decide how:

- a **sharp corner** (the direction turns by more than :data:`SMOOTH_TURN`) is where the
  robot stops; the single segments between sharp corners are timed jerk-limited by ruckig
  (phase-synchronised, so straight; checked) from rest to rest, the time-optimal straight
  move under every joint's velocity, acceleration and jerk limit;
- a **smooth corner** (a dense path, e.g. a Cartesian line as 30 waypoints a centimetre
  apart) is passed without stopping: the run of segments between sharp corners is timed
  along its arc length (:mod:`robocram.motion.arc_length_profile`) with per-segment
  velocity and acceleration caps and corner speeds that keep each joint's velocity step at
  a corner within ``acceleration * period``. Merging nearly collinear segments into one
  ruckig move instead would leave the polyline, so it is not done.

The trajectory is sampled every ``period`` and at every waypoint.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from robocram.motion.arc_length_profile import arc_length_run
from robocram.motion.errors import MotionError
from robocram.motion.joint_limits import JointLimits
from robocram.motion.joint_trajectory import FloatArray, JointTrajectory, TrajectoryPoint, still
from robocram.motion.straight_segment import straight_segment

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
    state: Callable[[float], State]  # global time -> positions, velocities, accelerations


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
        if float(np.linalg.norm(point - distinct[-1])) > SAME_POINT:
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
            pieces.append(_Piece(clock, clock + segment.duration, _shifted(segment.state, clock)))
        else:
            for arc in arc_length_run(waypoints[first : last + 1], limits, period):
                pieces.append(
                    _Piece(clock + arc.t_start, clock + arc.t_end, _shifted(arc.state, clock))
                )
        clock = pieces[-1].t1
    return pieces


def _shifted(state: Callable[[float], State], offset: float) -> Callable[[float], State]:
    return lambda t: state(t - offset)


def _runs(waypoints: list[FloatArray]) -> list[tuple[int, int]]:
    """Index ranges ``(first, last)`` of waypoints between sharp corners."""
    runs = []
    first = 0
    for k in range(1, len(waypoints) - 1):
        before = waypoints[k] - waypoints[k - 1]
        after = waypoints[k + 1] - waypoints[k]
        cos = float(np.dot(before, after) / (np.linalg.norm(before) * np.linalg.norm(after)))
        if math.acos(min(max(cos, -1.0), 1.0)) > SMOOTH_TURN:
            runs.append((first, k))
            first = k
    runs.append((first, len(waypoints) - 1))
    return runs


def _sampled(
    waypoints: list[FloatArray], pieces: list[_Piece], period: float
) -> tuple[TrajectoryPoint, ...]:
    """Points every ``period`` and at every waypoint; at a waypoint, its exact position."""
    stops = [pieces[0].t0] + [p.t1 for p in pieces]
    end = stops[-1]
    ticks = np.arange(int(math.floor(end / period)) + 1) * period
    where = np.clip(np.searchsorted(stops, ticks), 1, len(stops) - 1)
    gap = np.minimum(
        np.abs(ticks - np.take(stops, where)), np.abs(ticks - np.take(stops, where - 1))
    )
    times = sorted([*ticks[gap > SAME_TIME].tolist(), *stops])
    out = []
    piece = 0
    for t in times:
        while piece < len(pieces) - 1 and t > pieces[piece].t1 + SAME_TIME:
            piece += 1
        if t in stops:
            position, velocity, acceleration = _at_waypoint(waypoints, pieces, stops.index(t))
        else:
            position, velocity, acceleration = pieces[piece].state(t)
        out.append(
            TrajectoryPoint(
                tuple(position.tolist()),
                tuple(velocity.tolist()),
                tuple(acceleration.tolist()),
                float(t),
            )
        )
    return tuple(out)


def _at_waypoint(waypoints: list[FloatArray], pieces: list[_Piece], k: int) -> State:
    """Waypoint ``k`` exactly, with the mean of the motions arriving and leaving."""
    position = waypoints[k]
    zero = np.zeros_like(position)
    if k == 0 or k == len(waypoints) - 1:
        return position, zero, zero
    _, v_in, a_in = pieces[k - 1].state(pieces[k - 1].t1)
    _, v_out, a_out = pieces[k].state(pieces[k].t0)
    return position, 0.5 * (v_in + v_out), 0.5 * (a_in + a_out)


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

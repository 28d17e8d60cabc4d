"""Time a car's (Reeds-Shepp) base path on its curves, with continuous velocities.

A car's path is dense poses along arcs of constant curvature and straights (curvature
0), forwards or backwards. Timed as the polyline of its chords, the base's velocity
would turn at every pose (a step of velocity, 2 ms apart up to 120x the jerk limit); so the
path is cut into its **curves** instead: maximal runs of steps on one circle (or line),
driven one way. Each curve is driven from rest to rest along its own arc length by a
jerk-limited 1-D ruckig profile, the poses computed on the curve itself (they pass every
checked pose of the run, to rounding). At a cusp or a change of curvature the robot stops:
a curvature change at speed steps the yaw rate, which a differential base cannot do.

The caps on the path speed ``s_dot`` keep every joint within its limits, centripetal
terms included: with ``k`` the curvature, ``x' = cos(yaw) s_dot``,
``x'' = cos(yaw) s_ddot - k s_dot^2 sin(yaw)`` and
``x''' = cos(yaw) s_dddot - 3 k s_dot s_ddot sin(yaw) - k^2 s_dot^3 cos(yaw)``, so
``s_dot <= sqrt(a / 2k)``, ``s_ddot <= a / 2`` and
``s_dddot <= j - 3 k s_dot s_ddot - k^2 s_dot^3`` (and ``k s_dot``, ``k s_ddot``,
``k s_dddot`` within the yaw's limits). A step that lies on no single curve (where
the path switches inside it) is driven along its chord from rest to rest, as any polyline.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from robocram.motion.joint_limits import JointLimits
from robocram.motion.joint_trajectory import BASE_JOINTS, FloatArray, JointTrajectory
from robocram.motion.straight_segment import (
    profile_states,
    profile_switches,
    rest_to_rest,
    straight_segment,
)
from robocram.motion.time_parameterization import (
    SAME_POINT,
    TimedPiece,
    checked_path,
    sampled_trajectory,
    time_parameterize,
)

if TYPE_CHECKING:
    from ruckig import Trajectory

BoolArray = npt.NDArray[np.bool_]
ON_CURVE = 1e-7  # [m] a step whose chord is this far off the arc through its ends: mixed
SAME_CURVATURE = 1e-6  # [1/m] steps of curvatures this close are on one curve
END_TOLERANCE = 1e-6  # [m | rad] a curve must end this close to its last pose


@dataclass(frozen=True)
class CarCurve:
    """A curve driven from rest to rest: from ``start`` (x, y, yaw), ``direction`` +1
    forwards or -1 backwards, ``length`` [m] at ``curvature`` [1/m] (yaw per metre
    forwards, signed), timed by ``profile`` (1-D ruckig, the distance driven)."""

    start: FloatArray
    direction: float
    curvature: float
    length: float
    profile: Trajectory

    @property
    def duration(self) -> float:
        """Time from rest at the start to rest at the end [s]."""
        return float(self.profile.duration)

    def breaks(self) -> FloatArray:
        """The times [s] inside the curve where the path jerk changes."""
        return profile_switches(self.profile)

    def states(self, times: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Poses, velocities and accelerations of x, y, yaw at ``times`` [s]."""
        clock = np.minimum(np.maximum(times, 0.0), self.duration)
        s, s_dot, s_ddot = (c[:, 0] for c in profile_states(self.profile, clock))
        s = np.minimum(np.maximum(s, 0.0), self.length)
        d, k = self.direction, self.curvature
        signed = d * s
        half = 0.5 * k * signed
        yaw = self.start[2] + 2.0 * half
        chord = signed * np.sinc(half / math.pi)  # sin(half) / half, 1 at 0
        cos, sin = np.cos(yaw), np.sin(yaw)
        positions = np.stack(
            [
                self.start[0] + chord * np.cos(self.start[2] + half),
                self.start[1] + chord * np.sin(self.start[2] + half),
                yaw,
            ],
            axis=1,
        )
        speed = d * s_dot
        velocities = np.stack([speed * cos, speed * sin, k * speed], axis=1)
        turn = k * s_dot * s_dot
        push = d * s_ddot
        accelerations = np.stack(
            [push * cos - turn * sin, push * sin + turn * cos, k * push], axis=1
        )
        return positions, velocities, accelerations


def time_car_path(
    robot_name: str,
    poses: Sequence[Sequence[float]] | np.ndarray,
    limits: Sequence[JointLimits],
    *,
    period: float = 0.05,
) -> JointTrajectory:
    """Time a car's dense ``poses`` (x, y, continuous yaw) curve by curve, at rest between.

    Raises:
        MotionError: as :func:`~robocram.motion.time_parameterization.time_parameterize`.
    """
    points = np.array(checked_path(BASE_JOINTS, poses, limits, period))
    keep = np.concatenate([[True], np.abs(np.diff(points, axis=0)).max(axis=1) > SAME_POINT])
    points = points[keep]
    if len(points) < 3:
        return time_parameterize(
            robot_name, BASE_JOINTS, points, limits, kind="base", period=period
        )
    stops, pieces = _pieces(points, limits)
    return sampled_trajectory(robot_name, BASE_JOINTS, np.array(stops), pieces, period, "base")


def _steps(points: FloatArray) -> tuple[BoolArray, FloatArray, FloatArray]:
    """Per step: whether it lies on one curve, its signed length [m] and curvature [1/m]."""
    delta = np.diff(points, axis=0)
    mid = points[:-1, 2] + 0.5 * delta[:, 2]
    along = delta[:, 0] * np.cos(mid) + delta[:, 1] * np.sin(mid)
    lateral = -delta[:, 0] * np.sin(mid) + delta[:, 1] * np.cos(mid)
    signed = along / np.sinc(0.5 * delta[:, 2] / math.pi)
    moving = np.abs(signed) > SAME_POINT
    curvature = np.divide(delta[:, 2], signed, out=np.zeros(len(delta)), where=moving)
    return (np.abs(lateral) <= ON_CURVE) & moving, signed, curvature


def _pieces(
    points: FloatArray, limits: Sequence[JointLimits]
) -> tuple[list[FloatArray], list[TimedPiece]]:
    """The stops (curve ends) and the pieces between them."""
    on_curve, signed, curvature = _steps(points)
    same = (
        on_curve[1:]
        & on_curve[:-1]
        & (np.sign(signed[1:]) == np.sign(signed[:-1]))
        & (np.abs(curvature[1:] - curvature[:-1]) <= SAME_CURVATURE)
    )
    breaks = np.concatenate([[0], np.flatnonzero(~same) + 1, [len(signed)]])
    stops: list[FloatArray] = [points[0]]
    pieces: list[TimedPiece] = []
    for first, last in zip(breaks[:-1].tolist(), breaks[1:].tolist(), strict=True):
        curve = _curve(points, first, last, signed, limits) if on_curve[first] else None
        if curve is None:  # a switch inside the step, or a curve that misses its end
            for k in range(first, last):
                pieces.append(straight_segment(points[k], points[k + 1], limits))
                stops.append(points[k + 1])
        else:
            pieces.append(curve)
            stops.append(points[last])
    return stops, pieces


def _curve(
    points: FloatArray, first: int, last: int, signed: FloatArray, limits: Sequence[JointLimits]
) -> CarCurve | None:
    """The curve through ``points[first..last]``, timed; None if it misses ``points[last]``."""
    total = float(signed[first:last].sum())
    start = points[first]
    curvature = float(points[last, 2] - start[2]) / total
    length = abs(total)
    speed, accel, jerk = _caps(limits, abs(curvature))
    profile = rest_to_rest(np.zeros(1), np.array([length]), [speed], [accel], [jerk])
    curve = CarCurve(start, math.copysign(1.0, total), curvature, length, profile)
    end = curve.states(np.array([curve.duration]))[0][0]
    if np.abs(end - points[last]).max() > END_TOLERANCE:
        return None
    return curve


def _caps(limits: Sequence[JointLimits], curvature: float) -> tuple[float, float, float]:
    """Path speed, acceleration and jerk caps that keep x, y and yaw within limits on a
    curve of ``curvature`` [1/m] (see the module's docstring)."""
    xy, yaw = limits[:2], limits[2]
    v = min(lim.velocity for lim in xy)
    a = min(lim.acceleration for lim in xy)
    j = min(lim.jerk for lim in xy)
    if curvature == 0.0:
        return v, a, j
    speed = min(v, yaw.velocity / curvature, math.sqrt(a / (2.0 * curvature)))
    accel = min(0.5 * a, yaw.acceleration / curvature)
    while True:
        spare = j - 3.0 * curvature * speed * accel - curvature**2 * speed**3
        if spare >= 0.25 * j:  # always so for sensible limits; halving keeps it sound
            return speed, accel, min(spare, yaw.jerk / curvature)
        speed, accel = 0.5 * speed, 0.5 * accel

"""An independent judge of timed trajectories, for tests: finite differences and a
controller's interpolation, not the timing's own numbers.

- :func:`excess`: a trajectory sampled every :data:`DENSE` (2 ms) measured by finite
  differences of its positions: a k-th divided difference of positions 2 ms apart is the
  k-th derivative at some instant between them, so the largest may not exceed the limit;
  and the stored velocities and accelerations must equal the central differences within
  what a bounded jerk allows (``J h^2 / 6`` and ``J h / 3``).
- :func:`divided_excess`: the stored points alone, by their divided differences.
- :func:`hermite_excess`: the stored points as a ROS controller follows them, a quintic
  Hermite polynomial per interval from the stored positions, velocities and
  accelerations, its derivatives read at 21 instants per interval.
- :func:`assert_stored_steps_within`: between two stored points, velocity and
  acceleration change by at most limit x time apart (no two points 1 us apart with
  different velocities).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pytest

from robocram.motion import JointLimits, JointTrajectory

DENSE = 0.002  # [s] the judge's sampling period
SLACK = 1e-3  # relative excess tolerated over a limit (rounding of the profiles' tables)


@dataclass(frozen=True)
class Excess:
    """Largest ratio to its limit over joints and samples; residuals of stored values."""

    velocity: float
    acceleration: float
    jerk: float
    stored_velocity: float  # [/s] largest |stored - central difference| beyond J h^2 / 6
    stored_acceleration: float  # [/s^2] ... beyond J h / 3

    def within(self) -> bool:
        return (
            max(self.velocity, self.acceleration, self.jerk) <= 1.0 + SLACK
            and max(self.stored_velocity, self.stored_acceleration) <= 1e-6
        )


def _ticks(trajectory: JointTrajectory, period: float) -> tuple[np.ndarray, ...]:
    """The points at multiples of ``period`` (waypoint samples between them left out)."""
    times = trajectory.times()
    on_tick = np.abs(times / period - np.round(times / period)) < 1e-6
    rows = np.flatnonzero(on_tick)
    velocities = np.array([trajectory.points[i].velocities for i in rows])
    accelerations = np.array([trajectory.points[i].accelerations for i in rows])
    return times[rows], trajectory.positions()[rows], velocities, accelerations


def excess(dense: JointTrajectory, limits: tuple[JointLimits, ...]) -> Excess:
    """The judge: finite differences of the positions sampled every :data:`DENSE`."""
    t, q, v, a = _ticks(dense, DENSE)
    assert np.allclose(np.diff(t), DENSE, atol=1e-9)
    assert dense.duration - t[-1] < DENSE + 1e-9
    vel = np.array([lim.velocity for lim in limits])
    acc = np.array([lim.acceleration for lim in limits])
    jerk = np.array([lim.jerk for lim in limits])
    h = DENSE
    d1 = np.diff(q, axis=0) / h
    d2 = np.diff(q, n=2, axis=0) / h**2
    d3 = np.diff(q, n=3, axis=0) / h**3
    central_v = (q[2:] - q[:-2]) / (2 * h)
    stored_v = np.abs(v[1:-1] - central_v) - jerk * h * h / 6
    stored_a = np.abs(a[1:-1] - d2) - jerk * h / 3
    rounding = 4e-15 / h**3  # what rounding of positions near 1 does to a third difference
    return Excess(
        float(np.max(np.abs(d1) / vel)),
        float(np.max(np.abs(d2) / acc)),
        float(np.max((np.abs(d3) - rounding) / jerk)),
        float(np.max(stored_v)),
        float(np.max(stored_a)),
    )


def assert_stored_steps_within(
    trajectory: JointTrajectory, limits: tuple[JointLimits, ...]
) -> None:
    """Between two stored points, velocities change by at most acceleration x time apart,
    accelerations by at most jerk x time apart."""
    dt = np.diff(trajectory.times())[:, None]
    v = np.array([p.velocities for p in trajectory.points])
    a = np.array([p.accelerations for p in trajectory.points])
    acc = np.array([lim.acceleration for lim in limits])
    jerk = np.array([lim.jerk for lim in limits])
    assert np.all(np.abs(np.diff(v, axis=0)) <= acc * dt * (1 + SLACK) + 1e-9)
    assert np.all(np.abs(np.diff(a, axis=0)) <= jerk * dt * (1 + SLACK) + 1e-9)


def _limit_rows(limits: tuple[JointLimits, ...]) -> list[np.ndarray]:
    return [
        np.array([getattr(lim, n) for lim in limits]) for n in ("velocity", "acceleration", "jerk")
    ]


def divided_excess(trajectory: JointTrajectory, limits: tuple[JointLimits, ...]) -> list[float]:
    """Largest ratio to the limit of k! times the k-th divided differences (k = 1, 2, 3)
    of the stored positions."""
    t, d = trajectory.times(), trajectory.positions()
    found = []
    for k, limit in enumerate(_limit_rows(limits), start=1):
        d = (d[1:] - d[:-1]) / (t[k:] - t[:-k])[:, None]
        found.append(float(np.max(np.abs(d) * math.factorial(k) / limit)))
    return found


def hermite_excess(trajectory: JointTrajectory, limits: tuple[JointLimits, ...]) -> list[float]:
    """Largest ratio to the limit of velocity, acceleration and jerk of the quintic Hermite
    interpolation of the stored points (what a ROS joint trajectory controller follows)."""
    t, q = trajectory.times(), trajectory.positions()
    v = np.array([p.velocities for p in trajectory.points])
    a = np.array([p.accelerations for p in trajectory.points])
    h = np.diff(t)[:, None]
    step, v0, v1, a0, a1 = q[1:] - q[:-1], v[:-1], v[1:], a[:-1], a[1:]
    c3 = (20 * step - (8 * v1 + 12 * v0) * h - (3 * a0 - a1) * h**2) / (2 * h**3)
    c4 = (-30 * step + (14 * v1 + 16 * v0) * h + (3 * a0 - 2 * a1) * h**2) / (2 * h**4)
    c5 = (12 * step - 6 * (v1 + v0) * h + (a1 - a0) * h**2) / (2 * h**5)
    worst = [0.0, 0.0, 0.0]
    for u in np.linspace(0.0, 1.0, 21):
        tau = u * h
        rates = (
            v0 + a0 * tau + 3 * c3 * tau**2 + 4 * c4 * tau**3 + 5 * c5 * tau**4,
            a0 + 6 * c3 * tau + 12 * c4 * tau**2 + 20 * c5 * tau**3,
            6 * c3 + 24 * c4 * tau + 60 * c5 * tau**2,
        )
        for k, (rate, limit) in enumerate(zip(rates, _limit_rows(limits), strict=True)):
            worst[k] = max(worst[k], float(np.max(np.abs(rate) / limit)))
    return worst


def assert_same_motion(coarse: JointTrajectory, dense: JointTrajectory) -> None:
    """The usual trajectory's points are the dense one's at the same times."""
    assert coarse.duration == pytest.approx(dense.duration, abs=1e-9)
    times = dense.times()
    for point in coarse.points:
        row = int(np.argmin(np.abs(times - point.time_from_start)))
        if abs(times[row] - point.time_from_start) < 1e-9:
            assert dense.points[row].positions == pytest.approx(point.positions, abs=1e-9)
            assert dense.points[row].velocities == pytest.approx(point.velocities, abs=1e-9)


def assert_keeps_limits(
    coarse: JointTrajectory, dense: JointTrajectory, limits: tuple[JointLimits, ...]
) -> Excess:
    assert_same_motion(coarse, dense)
    assert_stored_steps_within(coarse, limits)
    assert max(divided_excess(coarse, limits)) <= 1.0 + SLACK
    assert max(hermite_excess(coarse, limits)) <= 1.0 + SLACK
    found = excess(dense, limits)
    assert found.within(), found
    return found

"""A run of short, gently turning segments, timed along its arc length without stopping.

A Cartesian line becomes dozens of joint-space waypoints a centimetre apart; stopping at
each would take seconds for a hand's width. Along such a run the robot moves on the
polyline at a path speed ``s_dot`` (``s`` the arc length in joint space), with:

- per segment, ``s_dot <= v_j / |u_j|`` and ``|s_ddot| <= a_j / |u_j|`` for every joint
  ``j`` (``u`` the segment's unit direction), so joint velocities and accelerations stay
  within limits inside the segment;
- at a corner, where the direction turns by ``du``, the joint velocities change at once by
  ``du_j * s_dot``; the corner speed is capped so that step is at most ``a_j * period``: a
  controller sampling every ``period`` sees no more than the acceleration limit;
- rest at both ends of the run.

The time-optimal speed under these caps is the usual forward-backward pass (accelerate as
hard as allowed, cruise, brake in time), so each segment is accelerate-cruise-brake.
The profile limits acceleration, not jerk: that is the price of never leaving the polyline.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from robocram.motion.joint_limits import JointLimits
from robocram.motion.joint_trajectory import FloatArray


@dataclass(frozen=True)
class Phase:
    """Constant path acceleration from ``t0`` for ``duration`` [s]."""

    t0: float  # [s] from the run's start
    s0: float  # arc length at t0
    speed: float  # path speed at t0
    acceleration: float  # path acceleration
    duration: float  # [s]


@dataclass(frozen=True)
class ArcSegment:
    """One segment of the run: its phases and its place on the path."""

    start: FloatArray
    direction: FloatArray  # unit, joint space
    length: float
    s_start: float  # arc length of ``start`` along the run
    phases: tuple[Phase, ...]

    @property
    def t_start(self) -> float:
        """Time the robot passes ``start`` [s] from the run's start."""
        return self.phases[0].t0

    @property
    def t_end(self) -> float:
        """Time the robot passes the segment's end [s] from the run's start."""
        last = self.phases[-1]
        return last.t0 + last.duration

    def state(self, t: float) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Positions, velocities, accelerations at ``t`` [s] from the run's start."""
        phase = self.phases[0]
        for candidate in self.phases:
            if t >= candidate.t0:
                phase = candidate
        tau = min(max(t - phase.t0, 0.0), phase.duration)
        s = phase.s0 + phase.speed * tau + 0.5 * phase.acceleration * tau * tau
        s = min(max(s, self.s_start), self.s_start + self.length)
        speed = max(phase.speed + phase.acceleration * tau, 0.0)
        u = self.direction
        return self.start + u * (s - self.s_start), u * speed, u * phase.acceleration


def arc_length_run(
    waypoints: Sequence[FloatArray], limits: Sequence[JointLimits], period: float
) -> tuple[ArcSegment, ...]:
    """Time the run through ``waypoints`` (distinct consecutive points), at rest at both ends."""
    starts = [np.asarray(p, dtype=float) for p in waypoints[:-1]]
    deltas = [np.asarray(b, dtype=float) - a for a, b in zip(starts, waypoints[1:], strict=True)]
    lengths = [float(np.linalg.norm(d)) for d in deltas]
    units = [d / n for d, n in zip(deltas, lengths, strict=True)]
    velocity = np.array([lim.velocity for lim in limits])
    acceleration = np.array([lim.acceleration for lim in limits])
    speed_caps = [_cap(velocity, u) for u in units]
    accel_caps = [_cap(acceleration, u) for u in units]
    node = [0.0] + [
        min(speed_caps[k - 1], speed_caps[k], _cap(acceleration * period, units[k] - units[k - 1]))
        for k in range(1, len(units))
    ] + [0.0]  # fmt: skip
    squared = [v * v for v in node]
    for k in range(len(units)):  # forward: no faster than accelerating from the last node
        squared[k + 1] = min(squared[k + 1], squared[k] + 2.0 * accel_caps[k] * lengths[k])
    for k in reversed(range(len(units))):  # backward: slow enough to brake for the next
        squared[k] = min(squared[k], squared[k + 1] + 2.0 * accel_caps[k] * lengths[k])
    segments = []
    t, s = 0.0, 0.0
    for k, unit in enumerate(units):
        phases = _segment_phases(
            t, s, lengths[k], squared[k], squared[k + 1], speed_caps[k], accel_caps[k]
        )
        segments.append(ArcSegment(starts[k], unit, lengths[k], s, phases))
        t, s = segments[-1].t_end, s + lengths[k]
    return tuple(segments)


def _cap(limit: FloatArray, share: FloatArray) -> float:
    """The path rate at which the first joint reaches its ``limit``: ``min limit_j/|share_j|``."""
    moving = np.abs(share) > 1e-15
    if not moving.any():
        return math.inf
    return float(np.min(limit[moving] / np.abs(share[moving])))


def _segment_phases(
    t0: float, s0: float, length: float, w0: float, w1: float, cap: float, accel: float
) -> tuple[Phase, ...]:
    """Accelerate from ``sqrt(w0)``, cruise at most at ``cap``, brake to ``sqrt(w1)``."""
    v0, v1 = math.sqrt(max(w0, 0.0)), math.sqrt(max(w1, 0.0))
    peak = min(cap, math.sqrt(max((w0 + w1 + 2.0 * accel * length) / 2.0, 0.0)))
    peak = max(peak, v0, v1)
    rise = (peak * peak - w0) / (2.0 * accel)
    fall = (peak * peak - w1) / (2.0 * accel)
    cruise = max(length - rise - fall, 0.0)
    phases = []
    t, s = t0, s0
    for distance, speed, acceleration, duration in (
        (rise, v0, accel, (peak - v0) / accel),
        (cruise, peak, 0.0, cruise / peak if peak > 0.0 else 0.0),
        (fall, peak, -accel, (peak - v1) / accel),
    ):
        if duration > 0.0:
            phases.append(Phase(t, s, speed, acceleration, duration))
            t, s = t + duration, s + distance
    return tuple(phases)

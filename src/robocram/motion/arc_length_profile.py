"""A run of short, gently turning segments, timed along its arc length without stopping.

A Cartesian line becomes a run of joint-space waypoints 2 cm of tool travel apart;
stopping at each would take seconds for a hand's width. Along such a run the robot moves on the
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
import numpy.typing as npt

from robocram.motion.joint_limits import JointLimits
from robocram.motion.joint_trajectory import FloatArray

IntArray = npt.NDArray[np.intp]


PHASE_FIELDS = 5  # a phase's row: t0 [s], s0, speed, acceleration, duration [s]
MAX_PHASES = 3  # accelerate, cruise, brake


@dataclass(frozen=True)
class ArcRun:
    """The timed run as tables, one row per segment (a polyline of ``m`` segments).

    A segment moves from ``starts[k]`` along the unit ``directions[k]`` for ``lengths[k]``;
    ``phases[k]`` holds up to :data:`MAX_PHASES` rows of constant path acceleration
    (``t0`` from the run's start, arc length ``s0`` and ``speed`` at ``t0``,
    ``acceleration``, ``duration``), unused rows starting at infinity. Sampling asks for
    hundreds of states per trajectory, so they are computed on the tables at once.
    """

    starts: FloatArray  # (m, joints)
    directions: FloatArray  # (m, joints), unit
    lengths: FloatArray  # (m,)
    s_starts: FloatArray  # (m,) arc length of each start along the run
    phases: FloatArray  # (m, MAX_PHASES, PHASE_FIELDS)
    t_starts: FloatArray  # (m,) [s] from the run's start: the robot passes ``starts[k]``
    t_ends: FloatArray  # (m,) [s] ... passes the segment's end

    def states(
        self, segments: IntArray, times: FloatArray
    ) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Positions, velocities, accelerations (one row each) on segment ``segments[i]``
        at ``times[i]`` [s] from the run's start: within its phase that began last."""
        table = self.phases[segments]  # (n, MAX_PHASES, PHASE_FIELDS)
        begun = np.count_nonzero(table[:, :, 0] <= times[:, None], axis=1)
        phase = table[np.arange(len(times)), np.maximum(begun - 1, 0)]
        t0, s0, speed0, acceleration, duration = phase.T
        tau = np.minimum(np.maximum(times - t0, 0.0), duration)
        s = s0 + speed0 * tau + 0.5 * acceleration * tau * tau
        s_start = self.s_starts[segments]
        s = np.minimum(np.maximum(s, s_start), s_start + self.lengths[segments])
        speed = np.maximum(speed0 + acceleration * tau, 0.0)
        u = self.directions[segments]
        return (
            self.starts[segments] + u * (s - s_start)[:, None],
            u * speed[:, None],
            u * acceleration[:, None],
        )


def arc_length_run(
    waypoints: Sequence[FloatArray], limits: Sequence[JointLimits], period: float
) -> ArcRun:
    """Time the run through ``waypoints`` (distinct consecutive points), at rest at both ends."""
    points = np.array(waypoints, dtype=float)
    starts = points[:-1]
    deltas = points[1:] - starts
    # as np.linalg.norm of each, bit for bit, without its wrapper (2 us a call)
    lengths = np.array([math.sqrt(float(d.dot(d))) for d in deltas])
    units = deltas / lengths[:, None]
    velocity = np.array([lim.velocity for lim in limits])
    acceleration = np.array([lim.acceleration for lim in limits])
    speed_caps = _caps(velocity, units).tolist()
    accel_caps = _caps(acceleration, units).tolist()
    corner_caps = _caps(acceleration * period, units[1:] - units[:-1]).tolist()
    lengths_list = lengths.tolist()
    node = [0.0] + [
        min(speed_caps[k - 1], speed_caps[k], corner_caps[k - 1]) for k in range(1, len(units))
    ] + [0.0]  # fmt: skip
    squared = [v * v for v in node]
    for k in range(len(units)):  # forward: no faster than accelerating from the last node
        squared[k + 1] = min(squared[k + 1], squared[k] + 2.0 * accel_caps[k] * lengths_list[k])
    for k in reversed(range(len(units))):  # backward: slow enough to brake for the next
        squared[k] = min(squared[k], squared[k + 1] + 2.0 * accel_caps[k] * lengths_list[k])
    phases = np.full((len(units), MAX_PHASES, PHASE_FIELDS), math.inf)
    t_starts, t_ends, s_starts = [], [], []
    t, s = 0.0, 0.0
    for k, length in enumerate(lengths_list):
        rows = _segment_phases(
            t, s, length, squared[k], squared[k + 1], speed_caps[k], accel_caps[k]
        )
        phases[k, : len(rows)] = rows
        t_starts.append(rows[0][0])
        s_starts.append(s)
        t = rows[-1][0] + rows[-1][4]
        t_ends.append(t)
        s += length
    return ArcRun(
        starts, units, lengths, np.array(s_starts), phases, np.array(t_starts), np.array(t_ends)
    )


def _caps(limit: FloatArray, shares: FloatArray) -> FloatArray:
    """Per row of ``shares``, the path rate at which the first joint reaches its
    ``limit``: ``min limit_j/|share_j|`` over the joints that move (infinite if none)."""
    size = np.abs(shares)
    moving = size > 1e-15
    rates = np.divide(limit, size, out=np.full(shares.shape, math.inf), where=moving)
    return rates.min(axis=1) if len(rates) else np.zeros(0)


def _segment_phases(
    t0: float, s0: float, length: float, w0: float, w1: float, cap: float, accel: float
) -> list[tuple[float, float, float, float, float]]:
    """Accelerate from ``sqrt(w0)``, cruise at most at ``cap``, brake to ``sqrt(w1)``:
    the phases of positive duration as ``(t0, s0, speed, acceleration, duration)``."""
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
            phases.append((t, s, speed, acceleration, duration))
            t, s = t + duration, s + distance
    return phases

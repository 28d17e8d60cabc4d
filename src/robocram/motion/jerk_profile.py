"""Ruckig's rest-to-rest profile as tables, sampled at many times at once.

A rest-to-rest profile of one section is, per joint, seven phases of constant jerk;
evaluating them for all times at once, with ruckig's own formula, costs what a few
``at_time`` calls and their conversion to arrays do. The tables are made once per
segment: timing samples each segment twice (its straightness check, then its points).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.joint_trajectory import FloatArray
from robocram.world.sorted_unique import sorted_unique

if TYPE_CHECKING:
    from ruckig import Trajectory

PHASES = 7  # of constant jerk per joint; phase 7 holds the end state, jerk 0
_BYTE_SUM = np.uint64(0x0101010101010101)  # times eight bytes: their sum in the top byte


@dataclass(frozen=True)
class JerkProfile:
    """Per joint, when its phases end, then per joint and phase the state it starts in."""

    ends: FloatArray  # (joints, 8) [s] ruckig's t_sum of each phase, at most the duration
    # (a time past the duration is in the end state), then infinity
    starts: FloatArray  # (6, joints * 8) time [s], position, velocity, acceleration, half
    # the acceleration and jerk at the start of phase k of joint i, in column 8 i + k

    def states(self, times: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Positions, velocities, accelerations at ``times`` (within the profile), one
        row per time: ruckig's ``at_time``, bit for bit."""
        t, p, v, a, half_a, j = self._phase_starts(times)
        return p + t * (v + t * (half_a + t * j / 6)), v + t * (a + t * j / 2), a + t * j

    def switches(self) -> FloatArray:
        """The times [s] strictly inside the profile where some joint's jerk changes,
        sorted (between two of them every joint's motion is one cubic polynomial)."""
        ends = self.ends[:, :PHASES]
        return sorted_unique(ends[(ends > 0.0) & (ends < ends.max())])

    def positions(self, times: FloatArray) -> FloatArray:
        """The positions of :meth:`states` alone."""
        t, p, v, _, half_a, j = self._phase_starts(times)
        return p + t * (v + t * (half_a + t * j / 6))

    def _phase_starts(self, times: FloatArray) -> FloatArray:
        """Time into its phase, then the phase's start state, per time and joint."""
        below = self.ends[None, :, :] <= times[:, None, None]  # (times, joints, 8) bools
        # eight bools are eight bytes 0 or 1: one product sums them, what count_nonzero
        # along the last axis does at a third of its cost
        phase = (below.view(np.uint64)[:, :, 0] * _BYTE_SUM) >> np.uint64(56)
        column = phase.astype(np.intp) + np.arange(0, self.starts.shape[1], PHASES + 1)
        state = np.take(self.starts, column, axis=1)  # (6, times, joints)
        state[0] = times[:, None] - state[0]
        return state


def jerk_profile(trajectory: Trajectory) -> JerkProfile | None:
    """The tables of a one-section profile without braking; None for any other."""
    profiles = trajectory.profiles
    if len(profiles) != 1 or any(p.brake.duration > 0.0 for p in profiles[0]):
        return None
    raw: list[float] = []
    for p in profiles[0]:  # per joint: 7 durations and jerks, 8 accelerations, ...
        raw += p.t
        raw += p.j
        raw += p.a
        raw += p.v
        raw += p.p
    table = np.array(raw).reshape(len(profiles[0]), 38)
    ends = table[:, :7].cumsum(axis=1)  # ruckig's t_sum; phase k starts at ends[k - 1]
    starts = np.empty((6, len(table), PHASES + 1))
    starts[0, :, 0] = 0.0
    starts[0, :, 1:] = ends
    starts[1], starts[2], starts[3] = table[:, 30:], table[:, 22:30], table[:, 14:22]
    starts[4] = table[:, 14:22] / 2
    starts[5, :, :7] = table[:, 7:14]
    starts[5, :, 7] = 0.0  # the end state
    last = np.full((len(table), PHASES + 1), np.inf)
    last[:, :7] = np.minimum(ends, float(trajectory.duration))  # ruckig: past the duration,
    # the end state, whatever a joint's own sum
    return JerkProfile(last, starts.reshape(6, -1))

"""Ruckig's rest-to-rest profile as tables, sampled at many times at once.

A rest-to-rest profile of one section is, per joint, seven phases of constant jerk;
evaluating them for all times at once, with ruckig's own formula, costs what a few
``at_time`` calls and their conversion to arrays do. The tables are made once per
segment: timing samples each segment twice (its straightness check, then its points).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ruckig import Trajectory

from robocram.motion.joint_trajectory import FloatArray

PHASES = 7  # of constant jerk per joint; phase 7 holds the end state, jerk 0
_BYTE_SUM = np.uint64(0x0101010101010101)  # times eight bytes: their sum in the top byte


@dataclass(frozen=True)
class JerkProfile:
    """Per joint, ruckig's phase ends, then per joint and phase its start state."""

    ends: FloatArray  # (joints, 8) [s] ruckig's t_sum of each phase, then infinity
    starts: FloatArray  # (6, joints * 8) time [s], position, velocity, acceleration, half
    # the acceleration and jerk at the start of phase k of joint i, in column 8 i + k
    duration: float  # [s]

    def states(self, times: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Positions, velocities, accelerations at ``times`` (within the profile), one
        row per time: ruckig's ``at_time``, bit for bit."""
        t, p, v, a, half_a, j = self._phase_starts(times)
        return p + t * (v + t * (half_a + t * j / 6)), v + t * (a + t * j / 2), a + t * j

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
        column[times >= self.duration] = np.arange(PHASES, self.starts.shape[1], PHASES + 1)
        state = np.take(self.starts, column, axis=1)  # (6, times, joints)
        state[0] = times[:, None] - state[0]
        return state


def jerk_profile(trajectory: Trajectory) -> JerkProfile | None:
    """The tables of a one-section profile without braking; None for any other."""
    profiles = trajectory.profiles
    if len(profiles) != 1 or any(p.brake.duration > 0.0 for p in profiles[0]):
        return None
    joints = profiles[0]
    width = len(joints)
    ends = np.cumsum(np.array([p.t for p in joints]), axis=1)  # (joints, 7): ruckig's t_sum
    acceleration = np.array([p.a for p in joints])
    starts = np.stack(
        [
            np.hstack((np.zeros((width, 1)), ends)),  # phase k starts at ends[k - 1]
            np.array([p.p for p in joints]),
            np.array([p.v for p in joints]),
            acceleration,
            acceleration / 2,
            np.hstack((np.array([p.j for p in joints]), np.zeros((width, 1)))),
        ]
    )
    return JerkProfile(
        np.hstack((ends, np.full((width, 1), np.inf))),
        starts.reshape(6, width * (PHASES + 1)),
        float(trajectory.duration),
    )

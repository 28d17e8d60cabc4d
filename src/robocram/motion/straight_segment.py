"""One straight joint-space segment, timed jerk-limited by ruckig from rest to rest.

Ruckig with phase synchronisation moves every joint through the same fraction of its
distance at every instant, so the joints travel the straight line between the two
waypoints. That is checked on the samples: a profile that strays more than
:data:`STRAIGHT_TOLERANCE` (ruckig falls back to time synchronisation when phase
synchronisation is infeasible) is replaced by a one-dimensional ruckig profile along the
segment's length, straight by construction, under the tightest joint's limits.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.errors import MotionError
from robocram.motion.jerk_profile import JerkProfile, jerk_profile
from robocram.motion.joint_limits import JointLimits
from robocram.motion.joint_trajectory import FloatArray
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import ruckig
    from ruckig import Trajectory
else:
    ruckig = LazyLibrary("ruckig")

STRAIGHT_TOLERANCE = 1e-6  # [rad | m] largest distance of a ruckig sample from the line
CHECK_SAMPLES = 64  # samples per segment on which straightness is checked


@dataclass(frozen=True)
class StraightSegment:
    """A timed straight move from ``start`` to ``end``, at rest at both ends."""

    start: FloatArray
    end: FloatArray
    trajectory: Trajectory  # ruckig: multi-joint (phase-synchronised) or 1-D along the line
    along_line: bool  # True: ``trajectory`` is 1-D, the distance travelled along the line

    @property
    def duration(self) -> float:
        """Time from rest at ``start`` to rest at ``end`` [s]."""
        return float(self.trajectory.duration)

    @cached_property
    def _line(self) -> tuple[float, FloatArray]:
        """The segment's length and unit direction: sampling asks for them per point."""
        delta = self.end - self.start
        length = float(np.linalg.norm(delta))
        return length, delta / length

    @cached_property
    def _profile(self) -> JerkProfile | None:
        """Ruckig's profile as tables (None: asked of ruckig time by time)."""
        return jerk_profile(self.trajectory)

    def breaks(self) -> FloatArray:
        """The times [s] inside the segment where a joint's jerk changes (none known
        for a profile not kept as tables)."""
        profile = self._profile
        return np.zeros(0) if profile is None else profile.switches()

    def _sampled(self, times: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Ruckig's states at ``times`` (within the profile), one row per time."""
        profile = self._profile
        return profile_states(self.trajectory, times) if profile is None else profile.states(times)

    def state(self, t: float) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Positions, velocities and accelerations at ``t`` [s] after the segment's start.

        Positions are projected onto the segment, so they lie on it exactly.
        """
        length, direction = self._line
        pos, vel, acc = self.trajectory.at_time(min(max(t, 0.0), self.duration))
        if self.along_line:
            s, s_dot, s_ddot = float(pos[0]), float(vel[0]), float(acc[0])
        else:
            s = float(np.dot(np.asarray(pos) - self.start, direction))
            s_dot = float(np.dot(vel, direction))
            s_ddot = float(np.dot(acc, direction))
        s = min(max(s, 0.0), length)
        return self.start + direction * s, direction * s_dot, direction * s_ddot

    def states(self, times: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """:meth:`state` at each of ``times`` [s]: arrays of one row per time.

        A trajectory is sampled at a hundred times per segment; one numpy pass over
        all of them costs what a few single samples do.
        """
        length, direction = self._line
        clock = np.minimum(np.maximum(times, 0.0), self.duration)
        pos, vel, acc = self._sampled(clock)
        if self.along_line:
            s, s_dot, s_ddot = pos[:, 0], vel[:, 0], acc[:, 0]
        else:
            s, s_dot, s_ddot = (pos - self.start) @ direction, vel @ direction, acc @ direction
        s = np.minimum(np.maximum(s, 0.0), length)
        return (  # np.outer, without its wrapper
            self.start + s[:, None] * direction,
            s_dot[:, None] * direction,
            s_ddot[:, None] * direction,
        )


def straight_segment(
    start: FloatArray, end: FloatArray, limits: Sequence[JointLimits]
) -> StraightSegment:
    """Time the straight move ``start`` -> ``end`` (distinct points) under ``limits``."""
    synced = rest_to_rest(
        start,
        end,
        [lim.velocity for lim in limits],
        [lim.acceleration for lim in limits],
        [lim.jerk for lim in limits],
    )
    segment = StraightSegment(start, end, synced, along_line=False)
    if _deviation(segment) <= STRAIGHT_TOLERANCE:
        return segment
    return along_line_segment(start, end, limits)


def along_line_segment(
    start: FloatArray, end: FloatArray, limits: Sequence[JointLimits]
) -> StraightSegment:
    """Time the move as one coordinate, the distance along the line, under the joints' caps.

    A joint moving a fraction ``|u_j|`` of the distance caps the line's velocity at
    ``v_j / |u_j|`` (and likewise acceleration and jerk); the tightest joint wins.
    """
    delta = end - start
    length = float(np.linalg.norm(delta))
    share = np.abs(delta) / length
    moving = share > 0.0

    def cap(values: Sequence[float]) -> float:
        return float(np.min(np.asarray(values, dtype=float)[moving] / share[moving]))

    line = rest_to_rest(
        np.zeros(1),
        np.array([length]),
        [cap([lim.velocity for lim in limits])],
        [cap([lim.acceleration for lim in limits])],
        [cap([lim.jerk for lim in limits])],
    )
    return StraightSegment(start, end, line, along_line=True)


def rest_to_rest(
    start: FloatArray,
    end: FloatArray,
    velocity: Sequence[float],
    acceleration: Sequence[float],
    jerk: Sequence[float],
) -> Trajectory:
    """Ruckig's offline, phase-synchronised, rest-to-rest profile."""
    dofs = len(start)
    params = ruckig.InputParameter(dofs)
    params.current_position = [float(v) for v in start]
    params.target_position = [float(v) for v in end]
    params.current_velocity = [0.0] * dofs
    params.current_acceleration = [0.0] * dofs
    params.target_velocity = [0.0] * dofs
    params.target_acceleration = [0.0] * dofs
    params.max_velocity = [float(v) for v in velocity]
    params.max_acceleration = [float(v) for v in acceleration]
    params.max_jerk = [float(v) for v in jerk]
    params.synchronization = ruckig.Synchronization.Phase
    trajectory = ruckig.Trajectory(dofs)
    result = ruckig.Ruckig(dofs).calculate(params, trajectory)
    if result not in (ruckig.Result.Working, ruckig.Result.Finished):
        raise MotionError(
            f"ruckig could not time the segment {list(start)} -> {list(end)}: {result}; "
            "check that the joint limits are positive and finite"
        )
    return trajectory


def _deviation(segment: StraightSegment) -> float:
    """Largest distance of the raw ruckig samples from the segment's line [rad | m]."""
    direction = segment._line[1]
    times = np.linspace(0.0, segment.duration, CHECK_SAMPLES)
    profile = segment._profile
    if profile is None:
        positions = profile_states(segment.trajectory, times)[0]
    else:
        positions = profile.positions(times)
    offsets = positions - segment.start
    off_line = offsets - (offsets @ direction)[:, None] * direction
    # np.linalg.norm(off_line, axis=1).max(), bit for bit: the root of the largest square
    return math.sqrt(float(np.add.reduce(off_line * off_line, axis=1).max()))


def profile_states(
    trajectory: Trajectory, times: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Ruckig's ``at_time`` at each of ``times`` (within the trajectory): positions,
    velocities, accelerations, one row per time.

    A one-section profile without braking is evaluated on its tables
    (:mod:`robocram.motion.jerk_profile`); anything else is asked of ruckig time by time.
    """
    profile = jerk_profile(trajectory)
    if profile is not None:
        return profile.states(times)
    samples = np.array([trajectory.at_time(float(t)) for t in times], dtype=float)
    return samples[:, 0], samples[:, 1], samples[:, 2]


def profile_switches(trajectory: Trajectory) -> FloatArray:
    """The times [s] strictly inside ``trajectory`` where a joint's jerk changes (none
    for a profile that is not one section without braking)."""
    profile = jerk_profile(trajectory)
    return np.zeros(0) if profile is None else profile.switches()

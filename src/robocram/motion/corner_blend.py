"""Gentle corners of a dense path passed without stopping, on blends that are checked.

A joint-space polyline passed at speed steps the joint velocities at every corner, so
:func:`~robocram.motion.time_parameterization.time_parameterize` rests at each; on a tool
line (waypoints 2 cm of tool travel apart, turning ~0.2 rad in joint space at each) that
doubles the time. Here a corner ``w`` between unit directions ``u1`` and ``u2`` is
replaced by a **blend** over the last ``b`` of the segment before it and the first ``b``
of the one after it (``b`` its radius, [rad | m] of the polyline's length ``s``): the
direction turns from ``u1`` to ``u2`` by a cubic smoothstep ``sigma(x) = 3x^2 - 2x^3``,
so along ``s``

- ``q'(s) = u1 + (u2 - u1) sigma``: continuous, each joint's within its segments';
- ``q''(s) = (u2 - u1) sigma' / 2b``, at most ``0.75 |u2 - u1| / b``;
- ``q'''(s) = (u2 - u1) sigma'' / 4b^2``, at most ``1.5 |u2 - u1| / b^2``;
- every joint stays between its values at the blend's ends and the corner (position
  limits hold), and the blend is within ``3 b |u2 - u1| / 16`` of the polyline.

**Checked.** The blend leaves the checked polyline, so it is walked on the same checker
before it is used (:func:`blend_radii`), as a straight segment is
(:func:`~robocram.motion.segment_check.segment_free`): conservative advancement on the
checker's clearances along the blend itself (a link clear by ``c`` stays free while no
point of it moves farther; :class:`TravelBound`), steps of at least 1 cm of travel, the
contact check deciding where a link touches. A blend not found free is tried at a
quarter of its radius, then the robot rests at that corner.

**Timed.** A run of blended corners is one jerk-limited 1-D ruckig profile ``s(t)`` from
rest to rest. With ``g1, g2, g3`` the bounds of ``|q'|, |q''|, |q'''|`` per joint over
the run, ``q_dot = q' s_dot``, ``q_ddot = q'' s_dot^2 + q' s_ddot`` and
``q_dddot = q''' s_dot^3 + 3 q'' s_dot s_ddot + q' s_dddot``; so the caps
``s_ddot <= alpha a / g1``, ``s_dddot <= alpha j / g1``, ``s_dot <= v / g1``,
``g2 s_dot^2 <= (1 - alpha) a`` and ``g3 s_dot^3 + 3 g2 s_dot s_ddot <= (1 - alpha) j``
keep every joint's velocity, acceleration and jerk within its limits at every instant,
whatever ``alpha``; the fastest of :data:`SHARES` is taken, or resting at every corner
when that is faster still.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.configuration_checker import (
    ClearanceChecker,
    ConfigurationChecker,
    can_tell_clearance,
    can_tell_near,
    posed,
)
from robocram.motion.joint_limits import JointLimits
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.segment_check import rigid_step
from robocram.motion.straight_segment import (
    along_line_segment,
    profile_states,
    profile_switches,
    rest_to_rest,
)
from robocram.motion.travel_bound import TravelBound
from robocram.world.sorted_unique import sorted_unique

if TYPE_CHECKING:
    from ruckig import Trajectory

SHARP_TURN = 1.0  # [rad | m per rad | m] |u2 - u1| above which the robot rests (60 deg)
SHARES = (0.25, 0.5, 0.75)  # alpha: the share of acceleration and jerk left to s_ddot
MAX_WALK = 64  # clearance queries a blend may spend before it counts as not proven free
SHRINK = 0.25  # a blend not proven free is tried again at this share of its radius


@dataclass(frozen=True)
class BlendedRun:
    """A polyline with its inner corners blended, timed from rest to rest by ``profile``
    (1-D ruckig along ``s``, the polyline's own length)."""

    points: FloatArray  # (m + 1, joints) waypoints
    units: FloatArray  # (m, joints) segment directions
    s_points: FloatArray  # (m + 1,) polyline length at each waypoint
    radii: FloatArray  # (m - 1,) blend radius of each inner corner, > 0
    profile: Trajectory

    @property
    def duration(self) -> float:
        """Time from rest at the first waypoint to rest at the last [s]."""
        return float(self.profile.duration)

    def breaks(self) -> FloatArray:
        """The times [s] inside the run where the jerk may jump: the profile's switches
        and the ends of the blends (where the path's third derivative does)."""
        corners = self.s_points[1:-1]
        edges = np.concatenate([corners - self.radii, corners + self.radii])
        found = [self.profile.get_first_time_at_position(0, float(s)) for s in edges]
        times = np.array([t for t in found if t is not None], dtype=float)
        return sorted_unique(np.concatenate([profile_switches(self.profile), times]))

    def states(self, times: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Positions, velocities, accelerations at ``times`` [s], one row per time."""
        clock = np.minimum(np.maximum(times, 0.0), self.duration)
        s, s_dot, s_ddot = (c[:, 0] for c in profile_states(self.profile, clock))
        q, q1, q2 = self.geometry(np.minimum(np.maximum(s, 0.0), self.s_points[-1]))
        return q, q1 * s_dot[:, None], q2 * (s_dot * s_dot)[:, None] + q1 * s_ddot[:, None]

    def geometry(self, s: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """``q``, ``dq/ds`` and ``d2q/ds2`` at the polyline lengths ``s``."""
        segments = len(self.units)
        seg = np.clip(self.s_points.searchsorted(s, side="right") - 1, 0, segments - 1)
        q = self.points[seg] + self.units[seg] * (s - self.s_points[seg])[:, None]
        q1 = self.units[seg].copy()
        q2 = np.zeros_like(q)
        for corner in (seg, seg + 1):  # the corner at the segment's start, at its end
            inner = (corner >= 1) & (corner <= segments - 1)
            c = np.where(inner, corner, 1)
            b = self.radii[c - 1]
            offset = s - self.s_points[c]
            mine = np.flatnonzero(inner & (np.abs(offset) < b))
            if len(mine):
                c, b, x = c[mine], b[mine], (offset[mine] + b[mine]) / (2.0 * b[mine])
                q[mine], q1[mine], q2[mine] = blend_state(
                    self.points[c], self.units[c - 1], self.units[c], b, x
                )
        return q, q1, q2


def blend_state(
    corner: FloatArray, u1: FloatArray, u2: FloatArray, b: FloatArray, x: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """``q``, ``dq/ds``, ``d2q/ds2`` on blends (rows) at fractions ``x`` in [0, 1]."""
    turn = u2 - u1
    sigma = x * x * (3.0 - 2.0 * x)
    area = x * x * x * (1.0 - 0.5 * x)  # the integral of sigma from 0
    two_b = (2.0 * b)[:, None]
    q = corner - u1 * b[:, None] + u1 * (two_b * x[:, None]) + turn * (two_b * area[:, None])
    q1 = u1 + turn * sigma[:, None]
    q2 = turn * (6.0 * x * (1.0 - x))[:, None] / two_b
    return q, q1, q2


def _blend_position(
    corner: FloatArray, u1: FloatArray, turn: FloatArray, b: float, x: float
) -> FloatArray:
    """:func:`blend_state`'s ``q`` of one blend at one fraction ``x``, the same operations
    on the same values (the same bits) without the rows a walk's single point does not
    need (a walk asks for one point per step)."""
    two_b = 2.0 * b
    area = x * x * x * (1.0 - 0.5 * x)
    return corner - u1 * b + u1 * (two_b * x) + turn * (two_b * area)


def _units(points: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Each segment's length and unit direction."""
    deltas = np.diff(points, axis=0)
    lengths = np.sqrt(np.add.reduce(deltas * deltas, axis=1))
    return lengths, deltas / lengths[:, None]


def blend_radii(
    checker: ConfigurationChecker, bound: TravelBound, path: Sequence[Sequence[float]]
) -> tuple[float, ...]:
    """Per inner waypoint of ``path`` (checked straight between waypoints), the radius of
    a blend proven free on ``checker`` (0: rest there). Half the shorter segment is tried
    first, then :data:`SHRINK` of it. Deterministic: counted queries, no clock."""
    points = np.array(path, dtype=float)
    if len(points) < 3 or not can_tell_clearance(checker):
        return (0.0,) * max(len(points) - 2, 0)
    lengths, units = _units(points)
    radii = []
    with posed(checker):
        for k in range(1, len(points) - 1):
            u1, u2 = units[k - 1], units[k]
            radius = 0.5 * min(lengths[k - 1], lengths[k])
            if not (np.isfinite(radius) and radius > 0.0) or _length(u2 - u1) > SHARP_TURN:
                radii.append(0.0)
                continue
            for b in (radius, SHRINK * radius):
                if _blend_free(checker, bound, points[k], u1, u2, b):
                    radii.append(b)
                    break
            else:
                radii.append(0.0)
    return tuple(radii)


def _blend_free(
    checker: ClearanceChecker,
    bound: TravelBound,
    corner: FloatArray,
    u1: FloatArray,
    u2: FloatArray,
    b: float,
) -> bool:
    """Whether the blend is free as a straight segment is (:func:`segment_free`'s walk):
    conservative advancement along the blend itself, each step moving no point of a
    link farther than that link's clearance where it starts (links not named are clear by
    the checker's reach), at least :data:`MAX_LINK_TRAVEL`; where a link touches, the
    contact check decides. Along the blend ``|dq_j/ds| <= max(|u1_j|, |u2_j|)``."""
    rate = np.maximum(np.abs(u1), np.abs(u2))
    speed = float(bound.lever @ rate)  # [m] the most any point moves per unit of s
    if speed <= 0.0:
        return True
    by_link: dict[str, float] = {}
    nearby = can_tell_near(checker)
    floor = bound.max_link_travel / speed
    s = 0.0
    turn = u2 - u1
    for _ in range(MAX_WALK):
        q = _blend_position(corner, u1, turn, b, min(s / (2.0 * b), 1.0))
        if nearby:  # only the labels that can limit the step are measured
            step, touching = rigid_step(
                checker.near(q),  # type: ignore[attr-defined]
                checker.reach,
                checker.reach / speed,
                lambda link: _link_travel(by_link, bound, link, rate),
            )
            if touching and not checker.is_free(q):
                return False
            s += max(step, floor)
            if s >= 2.0 * b:
                return True
            continue
        gaps = checker.clearances(q)
        if min(gaps.values(), default=1.0) <= 0.0 and not checker.is_free(q):
            return False
        step = checker.reach / speed
        for link, gap in gaps.items():
            if _link_travel(by_link, bound, link, rate) > 0.0:
                step = min(step, gap / by_link[link])
        s += max(step, floor)
        if s >= 2.0 * b:  # the rest is within this step (its end is on the polyline)
            return True
    return False


def _link_travel(
    by_link: dict[str, float], bound: TravelBound, link: str, rate: FloatArray
) -> float:
    """The most [m] a point of ``link`` moves per unit of ``s`` (kept in ``by_link``)."""
    found = by_link.get(link)
    if found is None:
        found = by_link[link] = bound.link_travel(link, np.zeros_like(rate), rate)
    return found


def _length(vector: FloatArray) -> float:
    return math.sqrt(float(vector.dot(vector)))


def blended_run(
    points: FloatArray, radii: FloatArray, limits: Sequence[JointLimits]
) -> BlendedRun | None:
    """``points`` timed through blends of ``radii`` (one per inner point, each > 0) from
    rest to rest; None when resting at every corner is as fast."""
    lengths, units = _units(points)
    s_points = np.concatenate([[0.0], np.cumsum(lengths)])
    velocity, acceleration, jerk = (
        np.array([getattr(lim, name) for lim in limits])
        for name in ("velocity", "acceleration", "jerk")
    )
    turns = np.abs(np.diff(units, axis=0))
    g1 = np.abs(units).max(axis=0)
    g2 = (0.75 * turns / radii[:, None]).max(axis=0)
    g3 = (1.5 * turns / (radii * radii)[:, None]).max(axis=0)
    profiles = []
    for alpha in SHARES:
        speed, accel, jolt = _caps(alpha, g1, g2, g3, velocity, acceleration, jerk)
        profiles.append(rest_to_rest(np.zeros(1), s_points[-1:], [speed], [accel], [jolt]))
    best = min(profiles, key=lambda profile: float(profile.duration))  # the first of ties
    if _resting_at_least(lengths, units, velocity, acceleration, jerk) <= best.duration:
        pairs = zip(points[:-1], points[1:], strict=True)
        resting = sum(along_line_segment(a, b, limits).duration for a, b in pairs)
        if resting <= best.duration:
            return None
    return BlendedRun(points, units, s_points, radii, best)


def _resting_at_least(
    lengths: FloatArray,
    units: FloatArray,
    velocity: FloatArray,
    acceleration: FloatArray,
    jerk: FloatArray,
) -> float:
    """A lower bound [s] on resting at every corner: per segment, the longest of the
    times each limit alone needs (``L / v``, ``2 sqrt(L / a)``, ``(32 L / j)^(1/3)``) at
    the segment's caps; ruckig is asked only when the blend is not faster than this."""
    size = np.abs(units)
    moving = size > 0.0

    def caps(limit: FloatArray) -> FloatArray:
        rates = np.divide(limit, size, out=np.full(size.shape, np.inf), where=moving)
        return rates.min(axis=1)

    times = np.maximum(
        np.maximum(lengths / caps(velocity), 2.0 * np.sqrt(lengths / caps(acceleration))),
        np.cbrt(32.0 * lengths / caps(jerk)),
    )
    return float(times.sum())


def _caps(
    alpha: float,
    g1: FloatArray,
    g2: FloatArray,
    g3: FloatArray,
    velocity: FloatArray,
    acceleration: FloatArray,
    jerk: FloatArray,
) -> tuple[float, float, float]:
    """Caps on ``s_dot``, ``s_ddot``, ``s_dddot`` for the share ``alpha`` (module doc)."""
    moving = g1 > 0.0
    accel = alpha * float((acceleration[moving] / g1[moving]).min())
    jolt = alpha * float((jerk[moving] / g1[moving]).min())
    speed = float((velocity[moving] / g1[moving]).min())
    bent = g2 > 0.0
    if bent.any():
        speed = min(speed, float(np.sqrt((1 - alpha) * acceleration[bent] / g2[bent]).min()))
    curled = g3 > 0.0
    if curled.any():  # g3 V^3 + 3 g2 A V = (1 - alpha) j: V^3 + p V - r = 0, one real root
        p = 3.0 * g2[curled] * accel / g3[curled]
        r = (1 - alpha) * jerk[curled] / g3[curled]
        root = np.sqrt(0.25 * r * r + p * p * p / 27.0)
        speed = min(speed, float((np.cbrt(0.5 * r + root) + np.cbrt(0.5 * r - root)).min()))
    return speed * (1.0 - 1e-9), accel, jolt  # the root's rounding kept inside

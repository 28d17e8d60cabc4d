"""Velocity, acceleration and jerk of a stored trajectory, from its positions alone.

Derivatives are divided differences of the stored positions at their stored times: the
``k``-th divided difference times ``k!`` is the ``k``-th derivative somewhere between its
nodes (mean value theorem), so a trajectory within its limits never shows one above them,
however its points are spaced. The robot is at rest before and after a trajectory: each
end is a triple node with velocity and acceleration zero, so a trajectory that starts
moving or stops at once shows the acceleration and jerk that takes. Angles that wrap
(continuous joints, the base's yaw) are unwrapped first.

A derivative is a finding when it exceeds its limit by more than ``limit_tolerance`` of
it plus the rounding error of its quotient (``k! 2^k 8 eps (1 + max|q|) / h^k`` over the
shortest span ``h``). Stored velocities and accelerations are compared at the inner
points with the derivative of the parabola through a point and its neighbours; they may
differ by the same share of the limit plus what a jerk at its limit changes in between
(``J h1 h2 / 6`` for velocities, ``J max(h1, h2)`` for accelerations).
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterator
from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from robocram.motion import JointLimits
from robocram.traces.audit_bounds import AuditBounds
from robocram.traces.audit_findings import AuditFinding, FindingKind, FindingPlace
from robocram.traces.trajectory_record import StoredTrajectory

FloatArray = NDArray[np.float64]
EPS = float(np.finfo(float).eps)
DERIVATIVES = (FindingKind.VELOCITY, FindingKind.ACCELERATION, FindingKind.JERK)


def limit_findings(
    trajectory: StoredTrajectory,
    limits: tuple[JointLimits, ...],
    bounds: AuditBounds,
    place: FindingPlace,
    wrapping: Collection[str] = (),
) -> Iterator[AuditFinding]:
    """Each joint's worst derivative over its limit, and stored values that disagree;
    the joints named in ``wrapping`` are angles that wrap (unwrapped first)."""
    if len(trajectory.points) < 2:
        return
    times = np.array([p.time_from_start for p in trajectory.points])
    positions = np.array([p.positions for p in trajectory.points], dtype=float)
    for column, limit in enumerate(limits):
        q = positions[:, column]
        if limit.name in wrapping:
            q = np.unwrap(q)
        yield from _derivative_findings(times, q, limit, bounds, place)
        yield from _stored_findings(trajectory, column, times, q, limit, bounds, place)


def _derivative_findings(
    times: FloatArray, q: FloatArray, limit: JointLimits, bounds: AuditBounds, place: FindingPlace
) -> Iterator[AuditFinding]:
    nodes = np.concatenate(([times[0]] * 2, times, [times[-1]] * 2))
    table = np.concatenate(([q[0]] * 2, q, [q[-1]] * 2))
    scale = 1.0 + float(np.max(np.abs(q)))
    shortest = float(np.min(np.diff(times)))
    caps = (limit.velocity, limit.acceleration, limit.jerk)
    for order, (kind, cap) in enumerate(zip(DERIVATIVES, caps, strict=True), start=1):
        span = nodes[order:] - nodes[:-order]
        step = np.diff(table)
        table = np.divide(step, span, out=np.zeros_like(step), where=span > 0.0)  # rest
        derivative = math.factorial(order) * np.abs(table)
        rounding = math.factorial(order) * 2**order * 8 * EPS * scale / shortest**order
        allowed = cap * (1.0 + bounds.limit_tolerance) + rounding
        worst = int(np.argmax(derivative))
        if derivative[worst] > allowed:
            at = float(np.mean(nodes[worst : worst + order + 1])) - float(times[0])
            found = place.finding(kind, at, f"joint {limit.name}", float(derivative[worst]), cap)
            yield _with_samples(found, int(np.count_nonzero(derivative > allowed)))


def _stored_findings(
    trajectory: StoredTrajectory,
    column: int,
    times: FloatArray,
    q: FloatArray,
    limit: JointLimits,
    bounds: AuditBounds,
    place: FindingPlace,
) -> Iterator[AuditFinding]:
    if len(times) < 3:
        return
    h1, h2 = np.diff(times)[:-1], np.diff(times)[1:]
    left, right = np.diff(q)[:-1] / h1, np.diff(q)[1:] / h2
    implied = {
        FindingKind.VELOCITY_MISMATCH: (left * h2 + right * h1) / (h1 + h2),
        FindingKind.ACCELERATION_MISMATCH: 2.0 * (right - left) / (h1 + h2),
    }
    slack = {
        FindingKind.VELOCITY_MISMATCH: limit.velocity * bounds.limit_tolerance
        + limit.jerk * h1 * h2 / 6.0,
        FindingKind.ACCELERATION_MISMATCH: limit.acceleration * bounds.limit_tolerance
        + limit.jerk * np.maximum(h1, h2),
    }
    inner = trajectory.points[1:-1]
    stored = {
        FindingKind.VELOCITY_MISMATCH: [p.velocities for p in inner],
        FindingKind.ACCELERATION_MISMATCH: [p.accelerations for p in inner],
    }
    for kind, values in stored.items():
        if not values or len(values[0]) <= column:  # a driver left them empty
            continue
        given = np.array([v[column] for v in values])
        gap = np.abs(given - implied[kind])
        over = gap - slack[kind]
        worst = int(np.argmax(over))
        if over[worst] > 0.0:
            at = float(times[worst + 1] - times[0])
            what = (
                f"joint {limit.name} stored {given[worst]:.4g}, implied {implied[kind][worst]:.4g}"
            )
            found = place.finding(kind, at, what, float(gap[worst]), float(slack[kind][worst]))
            yield _with_samples(found, int(np.count_nonzero(over > 0.0)))


def _with_samples(finding: AuditFinding, samples: int) -> AuditFinding:
    return replace(finding, samples=samples)

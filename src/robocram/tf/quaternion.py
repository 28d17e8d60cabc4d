"""Unit quaternions in ROS order ``(x, y, z, w)``, as plain tuples.

Small pure functions so that poses, IK and the world share one convention.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from robocram.tf.errors import PoseValueError, TfArgumentError

Quaternion = tuple[float, float, float, float]
IDENTITY: Quaternion = (0.0, 0.0, 0.0, 1.0)


def normalized(q: tuple[float, ...] | list[float]) -> Quaternion:
    """Return ``q`` scaled to unit length; raise on a zero or non-4 vector."""
    if len(q) != 4:
        raise PoseValueError(f"a quaternion has 4 components (x, y, z, w), got {len(q)}: {q!r}")
    x, y, z, w = float(q[0]), float(q[1]), float(q[2]), float(q[3])
    n = math.sqrt(x * x + y * y + z * z + w * w)  # the same sum, bit for bit, as ever
    if not math.isfinite(n):
        raise PoseValueError(f"quaternion {q!r} has a component that is not finite")
    if n < 1e-12:
        raise PoseValueError(f"quaternion {q!r} has no direction; use (0, 0, 0, 1) for no rotation")
    return (x / n, y / n, z / n, w / n)


def multiply(a: Quaternion, b: Quaternion) -> Quaternion:
    """Hamilton product ``a * b`` (rotate by ``b`` first, then by ``a``)."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def conjugate(q: Quaternion) -> Quaternion:
    """Inverse of a unit quaternion."""
    return (-q[0], -q[1], -q[2], q[3])


def rotate(q: Quaternion, v: tuple[float, float, float]) -> tuple[float, float, float]:
    """Rotate vector ``v`` by unit quaternion ``q``."""
    x, y, z, w = q
    # v' = v + 2w (q_v x v) + 2 q_v x (q_v x v)
    tx = 2.0 * (y * v[2] - z * v[1])
    ty = 2.0 * (z * v[0] - x * v[2])
    tz = 2.0 * (x * v[1] - y * v[0])
    return (
        v[0] + w * tx + (y * tz - z * ty),
        v[1] + w * ty + (z * tx - x * tz),
        v[2] + w * tz + (x * ty - y * tx),
    )


def to_matrix(q: Quaternion) -> NDArray[np.float64]:
    """3 x 3 rotation matrix of a unit quaternion."""
    x, y, z, w = q
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def from_matrix(m: NDArray[np.float64]) -> Quaternion:
    """Unit quaternion of a 3 x 3 rotation matrix (Shepperd's method)."""
    tr = float(m[0, 0] + m[1, 1] + m[2, 2])
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        q = ((m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s)
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2]) * 2
        q = (0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s)
    elif m[1, 1] > m[2, 2]:
        s = math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2]) * 2
        q = ((m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s)
    else:
        s = math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1]) * 2
        q = ((m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s, (m[1, 0] - m[0, 1]) / s)
    return normalized(tuple(float(c) for c in q))


def from_euler(roll: float, pitch: float, yaw: float) -> Quaternion:
    """Quaternion of fixed-axis roll, pitch, yaw [rad] (URDF's ``rpy`` convention)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    )


def to_euler(q: Quaternion) -> tuple[float, float, float]:
    """Roll, pitch, yaw [rad] of a unit quaternion (inverse of :func:`from_euler`).

    At pitch = +-pi/2 only roll - yaw (or roll + yaw) is defined; roll is then set to 0,
    so the angles still rebuild the same rotation.

    >>> [round(a, 6) for a in to_euler(from_euler(0.3, -1.5707963267948966, 0.2))]
    [0.0, -1.570796, 0.5]
    """
    m = to_matrix(q)
    cos_pitch = math.hypot(float(m[0, 0]), float(m[1, 0]))
    pitch = math.atan2(-float(m[2, 0]), cos_pitch)
    if cos_pitch > 1e-9:
        roll = math.atan2(float(m[2, 1]), float(m[2, 2]))
        yaw = math.atan2(float(m[1, 0]), float(m[0, 0]))
    else:
        roll = 0.0
        yaw = math.atan2(-float(m[0, 1]), float(m[1, 1]))
    return (roll, pitch, yaw)


def from_axis_angle(axis: tuple[float, float, float], angle: float) -> Quaternion:
    """Quaternion rotating by ``angle`` [rad] about ``axis`` (need not be unit)."""
    n = math.sqrt(sum(c * c for c in axis))
    if n < 1e-12:
        raise TfArgumentError(f"rotation axis {axis!r} has zero length")
    s = math.sin(angle / 2) / n
    return (axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle / 2))


def angle_between(a: Quaternion, b: Quaternion) -> float:
    """Smallest rotation angle [rad] taking orientation ``a`` to ``b``."""
    d = abs(sum(x * y for x, y in zip(a, b, strict=True)))
    return 2.0 * math.acos(min(1.0, d))


def slerp(a: Quaternion, b: Quaternion, t: float) -> Quaternion:
    """The rotation ``t`` (0..1) of the way from ``a`` to ``b`` along the shorter arc."""
    qa, qb = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    dot = float(qa @ qb)
    if dot < 0.0:  # q and -q are one rotation: take the shorter way round
        qb, dot = -qb, -dot
    if dot > 0.9995:  # nearly equal: a normalised straight blend is exact enough
        return normalized((qa + t * (qb - qa)).tolist())
    theta = float(np.arccos(min(dot, 1.0)))
    s = np.sin(theta)
    blend = (np.sin((1.0 - t) * theta) / s) * qa + (np.sin(t * theta) / s) * qb
    return normalized(blend.tolist())

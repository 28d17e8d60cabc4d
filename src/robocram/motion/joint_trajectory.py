"""A timed joint trajectory: what a motion becomes before anything moves.

Arm paths, Cartesian segments and base paths all end as a :class:`JointTrajectory`:
joint names and points, each with positions, velocities, accelerations and its time from
the start. It is plain frozen data, so it pickles to batch workers, goes into the trace
and becomes a ``FollowJointTrajectory`` goal unchanged. A base path is a trajectory of the
planar joints ``x``, ``y`` and ``yaw`` (:data:`BASE_JOINTS`) in the map frame.
"""

from __future__ import annotations

import bisect
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
BASE_JOINTS = ("x", "y", "yaw")  # [m, m, rad] in map: a base path's joints


@dataclass(frozen=True)
class TrajectoryPoint:
    """One point of a trajectory, in the order of the trajectory's joint names."""

    positions: tuple[float, ...]  # [rad | m]
    velocities: tuple[float, ...]  # [rad/s | m/s]
    accelerations: tuple[float, ...]  # [rad/s^2 | m/s^2]
    time_from_start: float  # [s]


@dataclass(frozen=True)
class JointTrajectory:
    """Joint names and timed points; ``kind`` says which motion made it (``arm``, ``base``)."""

    robot: str
    joint_names: tuple[str, ...]
    points: tuple[TrajectoryPoint, ...]
    kind: str = "arm"

    def __post_init__(self) -> None:
        width = len(self.joint_names)
        for i, point in enumerate(self.points):
            if len(point.positions) != width:
                raise ValueError(
                    f"trajectory point {i} has {len(point.positions)} positions for "
                    f"{width} joints {self.joint_names}"
                )
            if i and point.time_from_start <= self.points[i - 1].time_from_start:
                raise ValueError(
                    f"trajectory point {i} is at {point.time_from_start} s, not after point "
                    f"{i - 1} at {self.points[i - 1].time_from_start} s"
                )

    @property
    def duration(self) -> float:
        """Time from the start to the last point [s]."""
        return self.points[-1].time_from_start if self.points else 0.0

    @property
    def start(self) -> dict[str, float]:
        """Joint positions at the first point."""
        return dict(zip(self.joint_names, self.points[0].positions, strict=True))

    @property
    def end(self) -> dict[str, float]:
        """Joint positions at the last point."""
        return dict(zip(self.joint_names, self.points[-1].positions, strict=True))

    def positions(self) -> FloatArray:
        """All points' positions as an array of shape (points, joints)."""
        return np.array([p.positions for p in self.points], dtype=float).reshape(
            len(self.points), len(self.joint_names)
        )

    def times(self) -> FloatArray:
        """Every point's time from the start [s]."""
        return np.array([p.time_from_start for p in self.points], dtype=float)

    def at(self, t: float) -> FloatArray:
        """Positions at time ``t`` [s], linear between points (clamped to the ends)."""
        times = [p.time_from_start for p in self.points]
        if t <= times[0]:
            return np.array(self.points[0].positions)
        if t >= times[-1]:
            return np.array(self.points[-1].positions)
        i = bisect.bisect_right(times, t)
        a, b = self.points[i - 1], self.points[i]
        s = (t - a.time_from_start) / (b.time_from_start - a.time_from_start)
        return (1.0 - s) * np.array(a.positions) + s * np.array(b.positions)

    def sampled(self, period: float) -> Iterator[tuple[float, dict[str, float]]]:
        """``(t, {joint: position})`` every ``period`` [s], the last point included."""
        if period <= 0.0:
            raise ValueError(f"sampling period must be positive, got {period} s")
        steps = int(np.ceil(self.duration / period))  # a motion of no time: one sample
        for k in range(steps + 1):
            t = min(k * period, self.duration)
            yield t, dict(zip(self.joint_names, self.at(t).tolist(), strict=True))

    def to_ros(self) -> dict[str, object]:
        """The trajectory as a ``trajectory_msgs/JointTrajectory`` message dict."""
        points = []
        for p in self.points:
            secs = int(p.time_from_start)
            points.append(
                {
                    "positions": list(p.positions),
                    "velocities": list(p.velocities),
                    "accelerations": list(p.accelerations),
                    "time_from_start": {
                        "secs": secs,
                        "nsecs": int(round((p.time_from_start - secs) * 1e9)),
                    },
                }
            )
        return {"joint_names": list(self.joint_names), "points": points}


def still(robot: str, joint_names: Sequence[str], positions: Sequence[float]) -> JointTrajectory:
    """A one-point trajectory that holds ``positions`` (a motion that needs no move)."""
    zeros = tuple(0.0 for _ in joint_names)
    point = TrajectoryPoint(tuple(float(v) for v in positions), zeros, zeros, 0.0)
    return JointTrajectory(robot, tuple(joint_names), (point,))

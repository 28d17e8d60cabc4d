"""A timed joint trajectory: what a motion becomes before anything moves.

Arm paths, Cartesian segments and base paths all end as a :class:`JointTrajectory`:
joint names and points, each with positions, velocities, accelerations and its time from
the start. It is plain frozen data, so it pickles to batch workers, goes into the trace
and becomes a ``FollowJointTrajectory`` goal unchanged. A base path is a trajectory of the
planar joints ``x``, ``y`` and ``yaw`` (:data:`BASE_JOINTS`) in the map frame.

Its points are a tuple of :class:`TrajectoryPoint` or, as timing makes them, a
:class:`PointTable`: the same points kept as four arrays, each point made only when read.
Projection reads only the last point of the hundreds timing samples per motion.
"""

from __future__ import annotations

import bisect
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import overload

import numpy as np
import numpy.typing as npt

from robocram.motion.carried_joint import CarriedJoint
from robocram.motion.contact_allowance import ContactAllowance
from robocram.motion.errors import MotionError

FloatArray = npt.NDArray[np.float64]
BASE_JOINTS = ("x", "y", "yaw")  # [m, m, rad] in map: a base path's joints
BODY_JOINTS = ("x", "y", "z", "roll", "pitch", "yaw")  # [m, rad] in map: a flight's joints


@dataclass(frozen=True)
class TrajectoryPoint:
    """One point of a trajectory, in the order of the trajectory's joint names."""

    positions: tuple[float, ...]  # [rad | m]
    velocities: tuple[float, ...]  # [rad/s | m/s]
    accelerations: tuple[float, ...]  # [rad/s^2 | m/s^2]
    time_from_start: float  # [s]


class PointTable(Sequence[TrajectoryPoint]):
    """Points as rows of float64 arrays, read-only; a :class:`TrajectoryPoint` is made
    when one is read, with the very floats the arrays hold.

    Equal to the tuple of its points (and hashes as it), so a trajectory is equal to
    itself stored in a trace; it pickles as its arrays.
    """

    __slots__ = ("_accelerations", "_points", "_positions", "_times", "_velocities")

    def __init__(
        self,
        positions: FloatArray,  # (points, joints) [rad | m]
        velocities: FloatArray,  # (points, joints) [rad/s | m/s]
        accelerations: FloatArray,  # (points, joints) [rad/s^2 | m/s^2]
        times: FloatArray,  # (points,) [s] from the start
    ) -> None:
        # copies: the caller's arrays stay theirs, these are frozen
        columns = [np.array(c, dtype=float) for c in (positions, velocities, accelerations)]
        stamps = np.array(times, dtype=float)
        if stamps.ndim != 1 or any(c.ndim != 2 or len(c) != len(stamps) for c in columns):
            shapes = [c.shape for c in columns]
            raise MotionError(
                f"a point table needs (points, joints) positions, velocities and "
                f"accelerations and (points,) times, got {shapes} and {stamps.shape}"
            )
        for array in (*columns, stamps):
            array.flags.writeable = False
        self._positions, self._velocities, self._accelerations = columns
        self._times = stamps
        self._points: tuple[TrajectoryPoint, ...] | None = None

    @property
    def positions(self) -> FloatArray:
        """Every point's positions, shape (points, joints), read-only."""
        return self._positions

    @property
    def times(self) -> FloatArray:
        """Every point's time from the start [s], read-only."""
        return self._times

    def __len__(self) -> int:
        return len(self._times)

    @overload
    def __getitem__(self, index: int) -> TrajectoryPoint: ...

    @overload
    def __getitem__(self, index: slice) -> PointTable: ...

    def __getitem__(self, index: int | slice) -> TrajectoryPoint | PointTable:
        if isinstance(index, slice):
            return PointTable(
                self._positions[index],
                self._velocities[index],
                self._accelerations[index],
                self._times[index],
            )
        if self._points is not None:
            return self._points[index]
        return TrajectoryPoint(
            tuple(self._positions[index].tolist()),
            tuple(self._velocities[index].tolist()),
            tuple(self._accelerations[index].tolist()),
            float(self._times[index]),
        )

    def __iter__(self) -> Iterator[TrajectoryPoint]:
        return iter(self.as_tuple())

    def as_tuple(self) -> tuple[TrajectoryPoint, ...]:
        """All points (made once, then kept)."""
        if self._points is None:
            rows = (map(tuple, c.tolist()) for c in self._columns())
            self._points = tuple(map(TrajectoryPoint, *rows, self._times.tolist()))
        return self._points

    def _columns(self) -> tuple[FloatArray, FloatArray, FloatArray]:
        return self._positions, self._velocities, self._accelerations

    def __eq__(self, other: object) -> bool:
        if isinstance(other, PointTable):
            return self.as_tuple() == other.as_tuple()
        if isinstance(other, tuple):
            return self.as_tuple() == other
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self.as_tuple())

    def __repr__(self) -> str:
        return f"PointTable({self.as_tuple()!r})"

    def __reduce__(self) -> tuple[type[PointTable], tuple[FloatArray, ...]]:
        return PointTable, (*self._columns(), self._times)


@dataclass(frozen=True)
class JointTrajectory:
    """Joint names and timed points; ``kind`` says which motion made it (``arm``, ``base``).

    ``allowed_contacts`` are the contacts its motion was allowed beyond the description's
    (the audit of a trace honours them up to their depth); ``carried`` the joints of other
    objects it moves along (a drawer the hand pulls), which a replay moves with it.
    """

    robot: str
    joint_names: tuple[str, ...]
    points: tuple[TrajectoryPoint, ...] | PointTable
    kind: str = "arm"
    allowed_contacts: tuple[ContactAllowance, ...] = ()
    carried: tuple[CarriedJoint, ...] = ()

    def __post_init__(self) -> None:
        width = len(self.joint_names)
        if isinstance(self.points, PointTable):
            self._check_table(self.points, width)
            return
        for i, point in enumerate(self.points):
            if len(point.positions) != width:
                raise MotionError(
                    f"trajectory point {i} has {len(point.positions)} positions for "
                    f"{width} joints {self.joint_names}"
                )
            if i and point.time_from_start <= self.points[i - 1].time_from_start:
                raise MotionError(
                    f"trajectory point {i} is at {point.time_from_start} s, not after point "
                    f"{i - 1} at {self.points[i - 1].time_from_start} s"
                )

    def _check_table(self, table: PointTable, width: int) -> None:
        """The checks of the points one by one, on the arrays at once (same messages)."""
        if len(table) and table.positions.shape[1] != width:
            raise MotionError(
                f"trajectory point 0 has {table.positions.shape[1]} positions for "
                f"{width} joints {self.joint_names}"
            )
        times = table.times
        late = np.flatnonzero(times[1:] <= times[:-1])
        if len(late):
            i = int(late[0]) + 1
            raise MotionError(
                f"trajectory point {i} is at {float(times[i])} s, not after point "
                f"{i - 1} at {float(times[i - 1])} s"
            )

    @property
    def duration(self) -> float:
        """Time from the start to the last point [s]."""
        if isinstance(self.points, PointTable):
            return float(self.points.times[-1]) if len(self.points) else 0.0
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
        if isinstance(self.points, PointTable):
            return self.points.positions.copy()
        return np.array([p.positions for p in self.points], dtype=float).reshape(
            len(self.points), len(self.joint_names)
        )

    def times(self) -> FloatArray:
        """Every point's time from the start [s]."""
        if isinstance(self.points, PointTable):
            return self.points.times.copy()
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
            raise MotionError(f"sampling period must be positive, got {period} s")
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


def still(
    robot_name: str, joint_names: Sequence[str], positions: Sequence[float]
) -> JointTrajectory:
    """A one-point trajectory that holds ``positions`` (a motion that needs no move)."""
    zeros = tuple(0.0 for _ in joint_names)
    point = TrajectoryPoint(tuple(float(v) for v in positions), zeros, zeros, 0.0)
    return JointTrajectory(robot_name, tuple(joint_names), (point,))

"""A small 2-D turtle simulator: the tutorial robot of CRAM's beginner lessons.

The turtle lives on a square field (ROS turtlesim's 11 x 11 by default) but may leave it:
being out of bounds is something plans detect and recover from. It moves by integrating
a linear [m/s] and angular [rad/s] velocity over time steps; with the pen down it draws.
Consecutive collinear steps merge into one :class:`Line`, so a straight stroke is one line.
All methods are thread-safe.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass

from robocram.turtlesim.errors import TurtleArgumentError

Point = tuple[float, float]
_MERGE_ANGLE = 0.1  # [rad] a step this close to a line's direction extends the line


@dataclass(frozen=True)
class TurtlePose:
    """The turtle's position [m] on the field and heading ``theta`` [rad] (0 = +x)."""

    x: float
    y: float
    theta: float = 0.0

    @property
    def point(self) -> Point:
        """The position as ``(x, y)``."""
        return (self.x, self.y)

    def distance_to(self, x: float, y: float) -> float:
        """Distance [m] from the turtle to ``(x, y)``."""
        return math.hypot(x - self.x, y - self.y)


@dataclass(frozen=True)
class Line:
    """A stroke the pen drew from ``start`` to ``end`` in ``colour``."""

    start: Point
    end: Point
    colour: str

    @property
    def length(self) -> float:
        """Length [m] of the stroke."""
        return math.dist(self.start, self.end)


def wrap_angle(angle: float) -> float:
    """Return ``angle`` [rad] wrapped into ``(-pi, pi]``."""
    wrapped = math.atan2(math.sin(angle), math.cos(angle))
    return math.pi if wrapped == -math.pi else wrapped


class TurtleWorld:
    """The simulated field, turtle and pen.

    Args:
        size: side of the square field [m]; the field is ``[0, size] x [0, size]``.
        start: initial pose (default: the middle, facing +x).
        time_step: simulated seconds per integration step [s].
        step_delay: real seconds slept per step [s] (0 runs as fast as possible).
    """

    def __init__(
        self,
        size: float = 11.0,
        start: TurtlePose | None = None,
        time_step: float = 0.02,
        step_delay: float = 0.0,
    ) -> None:
        if size <= 0 or time_step <= 0 or step_delay < 0:
            raise TurtleArgumentError(
                f"TurtleWorld needs size > 0, time_step > 0 and step_delay >= 0, got "
                f"size={size}, time_step={time_step}, step_delay={step_delay}"
            )
        self.size = float(size)
        self.time_step = float(time_step)
        self.step_delay = float(step_delay)
        self._pose = start or TurtlePose(self.size / 2, self.size / 2, 0.0)
        self._pen_down = True
        self._colour = "white"
        self._lines: list[Line] = []
        self._steps = 0
        self._listeners: list[Callable[[TurtlePose], None]] = []
        self._lock = threading.RLock()

    @property
    def pose(self) -> TurtlePose:
        """The turtle's current pose."""
        with self._lock:
            return self._pose

    @property
    def pen_down(self) -> bool:
        """Whether the pen draws while the turtle moves."""
        with self._lock:
            return self._pen_down

    @property
    def colour(self) -> str:
        """The pen's colour."""
        with self._lock:
            return self._colour

    @property
    def lines(self) -> tuple[Line, ...]:
        """Strokes drawn so far, oldest first."""
        with self._lock:
            return tuple(self._lines)

    @property
    def steps(self) -> int:
        """Integration steps simulated so far."""
        with self._lock:
            return self._steps

    def in_field(self, x: float, y: float) -> bool:
        """Whether ``(x, y)`` lies on the field."""
        return 0.0 <= x <= self.size and 0.0 <= y <= self.size

    def set_pen(self, down: bool, colour: str | None = None) -> None:
        """Put the pen down (draw) or up, optionally changing its colour."""
        with self._lock:
            self._pen_down = bool(down)
            if colour is not None:
                self._colour = colour

    def add_listener(self, listener: Callable[[TurtlePose], None]) -> None:
        """Call ``listener(pose)`` after every change of the turtle's pose."""
        with self._lock:
            self._listeners.append(listener)

    def teleport(self, pose: TurtlePose) -> None:
        """Put the turtle at ``pose`` without drawing (a reset, not a motion)."""
        with self._lock:
            self._pose = pose
            listeners = tuple(self._listeners)
        for listener in listeners:
            listener(pose)

    def step(self, linear: float, angular: float) -> TurtlePose:
        """Integrate velocities ``linear`` [m/s] and ``angular`` [rad/s] over one time step."""
        if not (math.isfinite(linear) and math.isfinite(angular)):
            raise TurtleArgumentError(
                f"turtle velocities must be finite, got ({linear}, {angular})"
            )
        dt = self.time_step
        with self._lock:
            old = self._pose
            heading = old.theta + angular * dt / 2  # midpoint rule: arcs stay arcs
            new = TurtlePose(
                old.x + linear * dt * math.cos(heading),
                old.y + linear * dt * math.sin(heading),
                wrap_angle(old.theta + angular * dt),
            )
            self._pose = new
            self._steps += 1
            if self._pen_down and new.point != old.point:
                self._draw(old.point, new.point)
            listeners = tuple(self._listeners)
        for listener in listeners:
            listener(new)
        if self.step_delay:
            time.sleep(self.step_delay)
        return new

    def drive(self, linear: float, angular: float, duration: float = 1.0) -> TurtlePose:
        """Apply the velocities for ``duration`` [s] (turtlesim applies a twist for 1 s)."""
        if duration < 0:
            raise TurtleArgumentError(f"drive duration must be >= 0 [s], got {duration}")
        pose = self.pose
        for _ in range(round(duration / self.time_step)):
            pose = self.step(linear, angular)
        return pose

    def _draw(self, start: Point, end: Point) -> None:
        last = self._lines[-1] if self._lines else None
        if last is not None and last.end == start and last.colour == self._colour:
            line_dir = math.atan2(last.end[1] - last.start[1], last.end[0] - last.start[0])
            step_dir = math.atan2(end[1] - start[1], end[0] - start[0])
            if abs(wrap_angle(step_dir - line_dir)) < _MERGE_ANGLE:
                self._lines[-1] = Line(last.start, end, last.colour)
                return
        self._lines.append(Line(start, end, self._colour))

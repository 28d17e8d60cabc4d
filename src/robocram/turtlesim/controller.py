"""A go-to-goal controller for the turtle: turn towards the goal, then drive, then stop.

It steps the simulation (no teleporting) and calls ``check`` before every step, so a
plan that stops the motion (e.g. ``pursue``) interrupts it within one time step.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from robocram.execution.failures import NavigationGoalNotReached
from robocram.turtlesim.errors import TurtleArgumentError
from robocram.turtlesim.world import TurtlePose, TurtleWorld, wrap_angle


@dataclass(frozen=True)
class GoToGains:
    """Gains and limits of the controller; the defaults settle in about a second per metre."""

    linear_gain: float = 2.0  # [1/s] speed per metre of distance
    angular_gain: float = 8.0  # [1/s] turn rate per radian of heading error
    max_linear: float = 2.0  # [m/s]
    max_angular: float = 4.0  # [rad/s]
    drive_heading_error: float = 0.05  # [rad] drive only when heading this well
    tolerance: float = 0.05  # [m] close enough to the goal
    max_time: float = 60.0  # [s] simulated time before giving up


def go_to(
    world: TurtleWorld,
    x: float,
    y: float,
    gains: GoToGains | None = None,
    check: Callable[[], None] | None = None,
) -> TurtlePose:
    """Drive the turtle to ``(x, y)`` [m] and return its final pose.

    Raises:
        NavigationGoalNotReached: still away from the goal after ``gains.max_time``.
    """
    if not (math.isfinite(x) and math.isfinite(y)):
        raise TurtleArgumentError(f"turtle goal must be finite, got ({x}, {y})")
    g = gains or GoToGains()
    pose = world.pose
    for _ in range(math.ceil(g.max_time / world.time_step)):
        if check is not None:
            check()
        distance = pose.distance_to(x, y)
        if distance < g.tolerance:
            return pose
        error = wrap_angle(math.atan2(y - pose.y, x - pose.x) - pose.theta)
        angular = max(-g.max_angular, min(g.max_angular, g.angular_gain * error))
        linear = 0.0
        if abs(error) < g.drive_heading_error:
            linear = min(g.max_linear, g.linear_gain * distance)
        pose = world.step(linear, angular)
    raise NavigationGoalNotReached(
        f"the turtle stopped {pose.distance_to(x, y):.3f} m from ({x}, {y})",
        target=(x, y),
        reached=pose.point,
        error=pose.distance_to(x, y),
    )

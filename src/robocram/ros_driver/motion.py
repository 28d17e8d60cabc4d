"""How the driver moves the projected robot over time, so goals take time and can be cancelled.

Each motion is a series of small steps at ``STEP_RATE``; between steps the world lock is
released (the state publisher runs) and the goal's preemption is checked. Speeds and the
trajectory time scale come from the driver's options; a speed of 0 (or time scale 0)
makes the motion a single jump, as projection does.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from robocram.projection import ProjectedRobot
from robocram.projection.navigation import planar
from robocram.tf import Pose
from robocram.tf import quaternion as quat

STEP_RATE = 50.0  # [Hz]


@dataclass(frozen=True)
class MotionOptions:
    """Driver speeds: base [m/s] and [rad/s]; trajectories play at ``time_scale`` x their time."""

    base_speed: float = 0.5  # [m/s]
    base_turn_speed: float = 1.0  # [rad/s]
    time_scale: float = 1.0


class Stepper:
    """Runs a motion in steps under the world lock; stops early when told to."""

    def __init__(self, lock: threading.Lock, stopped: Callable[[], bool]) -> None:
        self.lock = lock
        self.stopped = stopped

    def run(self, duration: float, step: Callable[[float], None]) -> bool:
        """Call ``step(fraction)`` from 0 to 1 over ``duration`` [s]; False if stopped first."""
        steps = max(1, math.ceil(duration * STEP_RATE))
        for i in range(1, steps + 1):
            if self.stopped():
                return False
            with self.lock:
                step(i / steps)
            if i < steps:
                time.sleep(duration / steps)
        return True


def base_motion(
    robot: ProjectedRobot, goal: Pose, options: MotionOptions
) -> tuple[float, Callable[[float], None]]:
    """Duration [s] and step function moving the base in a straight line towards ``goal``."""
    start = robot.base_pose()
    target = planar(goal, start.position[2])
    yaw0 = quat.to_euler(start.orientation)[2]
    turn = math.remainder(quat.to_euler(target.orientation)[2] - yaw0, 2 * math.pi)
    distance = start.distance_to(target)
    duration = 0.0
    if options.base_speed > 0:
        duration = max(distance / options.base_speed, abs(turn) / options.base_turn_speed)

    def step(fraction: float) -> None:
        (x0, y0, z0), (x1, y1, _) = start.position, target.position
        position = (x0 + fraction * (x1 - x0), y0 + fraction * (y1 - y0), z0)
        yaw = yaw0 + fraction * turn
        robot.world.set_pose(robot.name, Pose(position, quat.from_euler(0.0, 0.0, yaw)))

    return duration, step


def joint_motion(
    robot: ProjectedRobot, goal: Mapping[str, float], seconds: float, options: MotionOptions
) -> tuple[float, Callable[[float], None]]:
    """Duration [s] and step function moving joints linearly to ``goal`` in ``seconds``."""
    start = robot.world.joint_states(robot.name)
    begin = {joint: start[joint] for joint in goal}

    def step(fraction: float) -> None:
        values = {j: begin[j] + fraction * (goal[j] - begin[j]) for j in goal}
        if fraction < 1.0:
            robot.world.set_joint_states(robot.name, values)

    return max(0.0, seconds * options.time_scale), step

"""Where a picture's camera goes so that it shows a robot at its task.

A fixed camera far off shows a whole kitchen and a robot a few pixels tall, hidden behind
the counter it works at. This one looks over the robot's shoulder, from behind and to one
side, and backs off just far enough that the robot and the things near it fit the view:
the viewer's first view and the demo's GIF use it.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from robocram.tf import Pose
from robocram.tf.optical_look_at import optical_look_at
from robocram.world.world import World
from robocram.world.world_object import RobotObject

NEAR_TASK = 2.5  # [m] items whose centre is this close to the robot's base are framed too
ELEVATION = math.radians(38.0)  # of the line from what is looked at up to the camera
SIDE = math.radians(35.0)  # the camera sits this far round from straight behind the robot
FOLLOW_ELEVATION = math.radians(55.0)  # steeper: a counter or wall seldom hides the robot
MARGIN = 1.15  # room around the framed bounds
MIN_DISTANCE = 1.5  # [m] from what is looked at
Bounds = tuple[tuple[float, float, float], tuple[float, float, float]]


@dataclass(frozen=True)
class Framing:
    """A camera's place and the point it looks at [m, map]."""

    eye: tuple[float, float, float]
    target: tuple[float, float, float]

    def pose(self) -> Pose:
        """The camera's optical-frame pose, as ``world.view.render`` takes it."""
        return Pose(self.eye, optical_look_at(self.eye, self.target))


def frame_bounds(
    bounds: Sequence[Bounds], heading: float, vertical_fov: float, elevation: float = ELEVATION
) -> Framing:
    """A camera behind ``heading`` [rad, the robot's yaw], ``elevation`` [rad] up, that fits
    every box of ``bounds`` into a view ``vertical_fov`` [rad] high (a picture's narrower
    side)."""
    low = np.min([b[0] for b in bounds], axis=0)
    high = np.max([b[1] for b in bounds], axis=0)
    centre = (low + high) / 2.0
    radius = float(np.linalg.norm(high - low)) / 2.0
    distance = max(MIN_DISTANCE, MARGIN * radius / math.sin(vertical_fov / 2.0))
    azimuth = heading + math.pi - SIDE
    back = np.array(
        [
            math.cos(elevation) * math.cos(azimuth),
            math.cos(elevation) * math.sin(azimuth),
            math.sin(elevation),
        ]
    )
    eye = centre + distance * back
    return Framing(_point(eye), _point(centre))


def task_bounds(world: World, robot: RobotObject) -> list[Bounds]:
    """The bounds of ``robot`` and of the items near it (not the environment, the floor or
    other robots): what a picture of the robot at its task must show."""
    base = np.array(world.pose(robot).position)
    found = [world.aabb(robot)]
    for obj in world.objects():
        if obj.type in ("environment", "floor", "robot") or obj is robot:
            continue
        low, high = world.aabb(obj)
        centre = (np.array(low) + np.array(high)) / 2.0
        if float(np.linalg.norm((centre - base)[:2])) <= NEAR_TASK:
            found.append((low, high))
    return found


def robot_heading(world: World, robot: RobotObject) -> float:
    """The yaw [rad] of ``robot``'s base in map."""
    x, y, z, w = world.pose(robot).orientation
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def frame_task(
    world: World, robot: RobotObject, vertical_fov: float, more: Iterable[Bounds] = ()
) -> Framing:
    """The framing of ``robot`` at its task in ``world`` now, with ``more`` bounds (where it
    went during a run, say) in the view too."""
    bounds = [*task_bounds(world, robot), *more]
    return frame_bounds(bounds, robot_heading(world, robot), vertical_fov)


@dataclass(frozen=True)
class Follower:
    """A camera that keeps a robot in the middle of the picture as it drives: aimed once
    over its shoulder at the size that frames it, then carried along with it, never turned
    or zoomed, so a film of a run is steady and the robot stays large enough to see its
    hands at work."""

    offset: tuple[float, float, float]  # [m] from the point looked at to the camera
    height: float  # [m] of the point looked at, kept while the robot drives

    @classmethod
    def of(cls, world: World, robot: RobotObject, vertical_fov: float) -> Follower:
        """Framing ``robot`` alone in ``world`` as it is now, from behind its heading."""
        heading = robot_heading(world, robot)
        framing = frame_bounds([world.aabb(robot)], heading, vertical_fov, FOLLOW_ELEVATION)
        offset = np.subtract(framing.eye, framing.target)
        return cls(_point(offset), framing.target[2])

    def framing(self, world: World, robot: RobotObject) -> Framing:
        """Where the camera is with ``robot`` where it is now in ``world``."""
        low, high = world.aabb(robot)
        target = np.array([(low[0] + high[0]) / 2, (low[1] + high[1]) / 2, self.height])
        return Framing(_point(target + np.array(self.offset)), _point(target))


def _point(values: np.ndarray) -> tuple[float, float, float]:
    return float(values[0]), float(values[1]), float(values[2])

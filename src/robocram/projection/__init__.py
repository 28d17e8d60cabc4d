"""Projection: a robot in the PyBullet world performing the same motions as a real one.

``with simulated_robot(world, "pr2"):`` starts the projected robot's process modules
(base, torso, head, perception, grippers, arms; flight and range sensing for flying
robots) and PERFORM sends motions to them. ``with recorded_robot("pr2", objects=...):``
runs the same plans without physics, only logging commands. ``prospect(robot, plan)``
(``robot = RobotHandle.of(world, "pr2")``) projects a plan and puts the world back: what
it would do, to choose before doing.
"""

from robocram.projection.errors import (
    ProjectionError,
    ProjectionUsageError,
)
from robocram.projection.neck import looking_orientation
from robocram.projection.perception import PerceivedObject
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.prospection import Prospect, prospect
from robocram.projection.recording import (
    RecordedState,
    RecordingRun,
    recorded_robot,
    recording_environment,
)
from robocram.projection.robot_environment import projection_environment
from robocram.projection.simulated_robot import SimulatedRun, simulated_robot
from robocram.projection.world_frames import LiveTransformTree, WorldFrames

__all__ = [
    "LiveTransformTree",
    "PerceivedObject",
    "ProjectedRobot",
    "ProjectionError",
    "ProjectionUsageError",
    "Prospect",
    "RecordedState",
    "RecordingRun",
    "SimulatedRun",
    "WorldFrames",
    "looking_orientation",
    "projection_environment",
    "prospect",
    "recorded_robot",
    "recording_environment",
    "simulated_robot",
]

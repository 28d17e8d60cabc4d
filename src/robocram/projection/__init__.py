"""Projection: a robot in the PyBullet world performing the same motions as a real one.

``with simulated_robot(world, "pr2"):`` starts the projected robot's process modules
(base, torso, head, perception, grippers, arms; flight and range sensing for flying
robots) and PERFORM sends motions to them. ``recording_environment`` runs the same plans
without physics, only logging commands.
"""

from robocram.projection.errors import ProjectionError
from robocram.projection.perception import PerceivedObject
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.robot_environment import projection_environment
from robocram.projection.simulated_robot import SimulatedRun, simulated_robot
from robocram.projection.world_frames import LiveTransformTree, WorldFrames

__all__ = [
    "LiveTransformTree",
    "PerceivedObject",
    "ProjectedRobot",
    "ProjectionError",
    "SimulatedRun",
    "WorldFrames",
    "projection_environment",
    "simulated_robot",
]

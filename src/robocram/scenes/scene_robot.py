"""A scene's robot: added, its kinematic model built, its arms parked, its feet on the floor.

Building the kinematic model here loads pinocchio and coal (~80 ms of C extensions) with
the robot, as a simulator loads its robot's models before the first command: else a
script's first plan pays for them and runs about twice as long as every later one.
"""

from __future__ import annotations

from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.robots import RobotDescription
from robocram.scenes.parking import park_arms
from robocram.scenes.standing import stand_on_the_floor
from robocram.tf import Pose
from robocram.world import World


def place_robot(world: World, desc: RobotDescription, pose: Pose) -> str:
    """Add ``desc`` to ``world`` at ``pose``, ready to plan with; its name in the world."""
    handle = world.add_robot(desc, pose=pose)
    model = handle.description.model
    if model is not None:
        robot_kinematics(model)
    name = handle.name
    park_arms(world, name)
    stand_on_the_floor(world, name)  # a legged robot's trunk: its feet on the floor
    return name

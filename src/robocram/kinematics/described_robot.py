"""What the kinematics layer accepts as "the robot": a description, a built-in robot's
name, or anything that carries a loaded description (the world's ``RobotHandle``, which
this layer may not import)."""

from __future__ import annotations

from typing import Protocol

from robocram.robots import LoadedDescription, RobotDescription


class DescribedRobot(Protocol):
    """A robot that knows its checked description."""

    @property
    def description(self) -> LoadedDescription:
        """The robot's description, its model loaded."""
        ...


RobotRef = RobotDescription | str | DescribedRobot
"""A description, a built-in robot's name, or a robot carrying its description."""


def description_of(robot: RobotRef) -> RobotDescription | str:
    """The description (or name) ``robot`` stands for."""
    if isinstance(robot, (RobotDescription, str)):
        return robot
    return robot.description

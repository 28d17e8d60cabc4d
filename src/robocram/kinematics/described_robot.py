"""What the kinematics layer accepts as "the robot": a description, a built-in robot's
name, or anything that carries a loaded description (the world's ``RobotHandle``, which
this layer may not import)."""

from __future__ import annotations

from typing import Protocol

from robocram.robots import LoadedDescription, RobotDescription, load_description


class DescribedRobot(Protocol):
    """A robot that knows its checked description."""

    @property
    def description(self) -> LoadedDescription:
        """The robot's description, its model loaded."""
        ...


RobotRef = RobotDescription | str | DescribedRobot
"""A description, a built-in robot's name, or a robot carrying its description."""


def description_of(robot: RobotRef) -> RobotDescription:
    """The description ``robot`` stands for: a name is looked up here, once, at the
    layer's public entry (``solve_ik``, ``reachable``, ``forward_kinematics``); the
    solvers below take descriptions only."""
    if isinstance(robot, str):
        return load_description(robot)
    if isinstance(robot, RobotDescription):
        return robot
    return robot.description

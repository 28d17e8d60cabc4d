"""Moving the torso in projection: clamp to the URDF limits, apply, fail if clamped."""

from __future__ import annotations

from robocram.execution.failures import TorsoGoalNotReached
from robocram.projection.errors import ProjectionError
from robocram.projection.projected_robot import ProjectedRobot


def torso_joint(robot: ProjectedRobot) -> str:
    """The robot's torso joint, or an error for robots without one."""
    joint = robot.description.torso_joint
    if joint is None:
        raise ProjectionError(
            f"{robot.name} has no torso joint (description.torso_joint is None); "
            "do not send it moving-torso motions"
        )
    return joint


def move_torso(robot: ProjectedRobot, goal: float) -> float:
    """Set the torso joint to ``goal`` [m | rad]; return the value reached.

    Raises:
        TorsoGoalNotReached: ``goal`` was outside the limits; the clamped value is applied.
    """
    joint = torso_joint(robot)
    value = float(goal)
    clamped = robot.world.set_joint_states(robot.name, {joint: value})
    reached = robot.world.joint_states(robot.name)[joint]
    if clamped:
        c = clamped[0]
        raise TorsoGoalNotReached(
            f"torso goal {value} of {robot.name} is outside [{c.lower}, {c.upper}]; "
            f"moved to {reached} instead",
            goal=value,
            limits=(c.lower, c.upper),
            reached=reached,
        )
    return reached

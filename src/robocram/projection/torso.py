"""Moving the torso in projection: a checked, timed trajectory to the goal within limits.

The lift moves everything above it (the head, the arms and what they hold), so its way
is checked against the world like an arm motion (``joint_motion.py``); a way that runs
into something (a shelf above the head) fails with ``TorsoPathBlocked`` before anything
moves. A goal outside the limits moves the torso to the nearest limit and then fails with
``TorsoGoalNotReached``, as CRAM's projection does.
"""

from __future__ import annotations

from robocram.execution.failures import (
    ManipulationPathBlocked,
    TorsoGoalNotReached,
    TorsoPathBlocked,
)
from robocram.motion.joint_goal import finite_goal
from robocram.projection.errors import ProjectionError
from robocram.projection.joint_motion import move_along_checked
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
    """Move the torso joint to ``goal`` [m | rad] along a checked trajectory; return the
    value reached.

    Raises:
        TorsoPathBlocked: the way there runs into something; the torso did not move.
        TorsoGoalNotReached: ``goal`` was outside the limits; the torso moved to the
            nearest limit.
        MotionInputError: ``goal`` is not a finite number (nothing moved).
    """
    joint = torso_joint(robot)
    value = finite_goal(joint, goal)
    limits = robot.world.bodies.joint_limits(robot.name, joint)
    inside = limits.clamp(value)
    start = robot.world.joint_states(robot.name)[joint]
    try:
        reached = move_along_checked(
            robot, {joint: inside}, kind="torso", what=f"{robot.name}'s torso"
        )[joint]
    except ManipulationPathBlocked as blocked:
        raise TorsoPathBlocked(
            f"{robot.name}'s torso cannot move from {start:.3f} to {inside:.3f}: {blocked}; "
            "it did not move",
            goal=value,
            limits=(limits.lower, limits.upper),
            colliding_pairs=blocked.colliding_pairs,
            path_fraction=blocked.path_fraction,
        ) from blocked
    if inside != value:
        raise TorsoGoalNotReached(
            f"torso goal {value} of {robot.name} is outside [{limits.lower}, {limits.upper}]; "
            f"moved to {reached} instead",
            goal=value,
            limits=(limits.lower, limits.upper),
            reached=reached,
        )
    return reached

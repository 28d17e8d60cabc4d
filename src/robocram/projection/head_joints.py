"""Turning the head (a pan-tilt head or a neck arm) to given joint values.

A plan reads the neck's parking configuration from the KB, as it does the arms', and
turns the head there with ``looking`` (``configuration``): a Boxy's neck, turned to
where it last looked, put its camera into the fridge at every stand in front of it.
The turn is checked and timed like every head motion (kind ``head``).
"""

from __future__ import annotations

from robocram.execution.failures import ManipulationPathBlocked, PtuPathBlocked
from robocram.motion.tool_goal import joint_values
from robocram.projection.errors import ProjectionError
from robocram.projection.joint_motion import move_along_checked
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots.looking_means import head_joints


def turn_head_joints(robot: ProjectedRobot, configuration: object) -> dict[str, float]:
    """Turn the head's joints to ``configuration`` ({joint: value} or [[joint, value], ...])
    along a checked, timed trajectory; return the values reached.

    Raises:
        ProjectionError: a joint is none of the head's.
        PtuPathBlocked: the turn runs into something; the head did not move.
    """
    values = joint_values(configuration)
    allowed = head_joints(robot.description)
    unknown = sorted(set(values) - allowed)
    if unknown:
        raise ProjectionError(
            f"joints {unknown} do not turn {robot.name}'s head; give the head's joints "
            f"{sorted(allowed)} (its neck_parking, pan/tilt or neck arm joints)"
        )
    what = f"{robot.name}'s head"
    try:
        return move_along_checked(robot, values, kind="head", what=what, plan=True)
    except ManipulationPathBlocked as blocked:
        raise PtuPathBlocked(
            f"{robot.name} cannot turn its head to {values}: {blocked}; the head did not move",
            colliding_pairs=blocked.colliding_pairs,
            path_fraction=blocked.path_fraction,
        ) from blocked

"""Trajectories that carry the joints a description couples to one actuator.

Robocram plans with the actuator of a :class:`~robocram.robots.JointCoupling` alone
(Stretch's ``joint_arm_l3``); the robot's URDF, and the controllers of its driver, know the
followers too. Before a trajectory is sent, each follower is added with the value the
coupling gives it at every point, so all the URDF's joints of the telescope move
consistently.
"""

from __future__ import annotations

from dataclasses import replace

from robocram.motion import JointTrajectory
from robocram.motion.joint_trajectory import TrajectoryPoint
from robocram.robots import RobotDescription


def with_coupled_followers(desc: RobotDescription, trajectory: JointTrajectory) -> JointTrajectory:
    """``trajectory`` with every follower of a coupled actuator in it (none: unchanged)."""
    names = list(trajectory.joint_names)
    added: list[tuple[str, int, float, float]] = []  # follower, actuator column, m, offset
    for coupling in desc.coupled_joints:
        if coupling.actuator not in names:
            continue
        column = names.index(coupling.actuator)
        for follower in coupling.followers:
            if follower not in names:
                added.append((follower, column, coupling.multiplier, coupling.offset))
    if not added:
        return trajectory
    points = tuple(_extended(point, added) for point in trajectory.points)
    joint_names = (*trajectory.joint_names, *(name for name, *_ in added))
    return replace(trajectory, joint_names=joint_names, points=points)


def _extended(
    point: TrajectoryPoint, added: list[tuple[str, int, float, float]]
) -> TrajectoryPoint:
    positions = [m * point.positions[c] + offset for _, c, m, offset in added]
    velocities = [m * point.velocities[c] for _, c, m, _ in added]
    accelerations = [m * point.accelerations[c] for _, c, m, _ in added]
    return TrajectoryPoint(
        (*point.positions, *positions),
        (*point.velocities, *velocities),
        (*point.accelerations, *accelerations),
        point.time_from_start,
    )

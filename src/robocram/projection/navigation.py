"""Driving in projection: the base jumps to its goal unless the goal is in collision.

Like CRAM's projected ``drive``: the robot is put at the target; if it then touches
anything that is neither the floor nor attached to it, the old pose is restored and
``NavigationPoseUnreachable`` names what it hit. The robot keeps its height above the
floor; only x, y and the yaw of the target count. IK that moves the base
(``kinematics.PlanarBase``) moves it the same way (:func:`place_base`), so what the robot
holds rides along.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterator

from robocram.execution.failures import NavigationPoseUnreachable
from robocram.kinematics import BaseMotion
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose, PoseLike, PoseStamped
from robocram.tf import quaternion as quat


def planar(pose: Pose, z: float) -> Pose:
    """``pose`` flattened onto the plane at height ``z`` [m]: x, y and yaw kept."""
    yaw = quat.to_euler(pose.orientation)[2]
    return Pose((pose.position[0], pose.position[1], z), quat.from_euler(0.0, 0.0, yaw))


def floor_names(robot: ProjectedRobot) -> list[str]:
    """Names of the world's floors (a standing robot always touches them)."""
    return [o.name for o in robot.world.objects("floor")]


def drive(robot: ProjectedRobot, target: PoseStamped | PoseLike) -> Pose:
    """Put the robot's base at ``target`` (map unless stamped); return the reached pose.

    Raises:
        NavigationPoseUnreachable: the robot would collide there; it stays where it was.
    """
    world = robot.world
    start = robot.base_pose()
    goal = planar(robot.in_map(target), start.position[2])
    if not all(math.isfinite(v) for v in goal.position):
        raise ValueError(f"navigation target {target!r} has a non-finite position")
    place_base(robot, goal)
    colliding = world.collisions(robot.name, ignore=floor_names(robot))
    if colliding:
        world.set_pose(robot.name, start)
        names = [o.name for o in colliding]
        raise NavigationPoseUnreachable(
            f"{robot.name} at {goal.position} would collide with {names}",
            target=target,
            colliding=names,
        )
    return goal


def place_base(robot: ProjectedRobot, goal: Pose) -> None:
    """Put the base at ``goal`` (map); what the robot holds rides along. No checks."""
    robot.world.set_pose(robot.name, goal)


def moved_base(robot: ProjectedRobot, motion: BaseMotion) -> Pose:
    """The base pose (map) after a planar ``motion`` in the base's own frame."""
    start = robot.base_pose()
    return planar(start * motion.pose(), start.position[2])


@contextlib.contextmanager
def base_moved_by(robot: ProjectedRobot, motion: BaseMotion | None) -> Iterator[None]:
    """Inside the block the base stands moved by ``motion`` (nothing if None); then back."""
    if motion is None:
        yield
        return
    start = robot.base_pose()
    place_base(robot, moved_base(robot, motion))
    try:
        yield
    finally:
        place_base(robot, start)

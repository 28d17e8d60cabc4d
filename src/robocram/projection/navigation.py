"""Driving in projection: the base follows a checked path to its goal.

``drive`` plans the base's path from where it stands to the target
(``motion.plan_base_path``: the straight way if it is free, else around what is in the
way), for the robot as it stands, with what it holds; then it follows the timed path. A
goal in collision raises ``NavigationPoseUnreachable``, a goal no free path reaches
``NavigationPathBlocked`` naming the blocker (the drawer the search left open); either
way the robot stays where it was. The robot keeps its height above the floor; only x, y
and the yaw of the target count. IK that moves the base (``kinematics.PlanarBase``) places
it with :func:`place_base`, so what the robot holds rides along.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Collection, Iterator
from dataclasses import replace

from robocram.execution.failures import NavigationPathBlocked, NavigationPoseUnreachable
from robocram.kinematics import BaseMotion
from robocram.motion import (
    BASE_JOINTS,
    JointTrajectory,
    joint_limits,
    plan_base_path,
    time_parameterize,
)
from robocram.motion.hand_contact import HandContact
from robocram.motion.hand_sweep import hand_breach
from robocram.projection.errors import ProjectionError
from robocram.projection.path_watch import planned_against
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.trajectory_follower import follow
from robocram.tf import Pose, PoseLike, PoseStamped
from robocram.tf import quaternion as quat

FIXED_TOLERANCE = 1e-3  # [m | rad] a fixed base "drives" only to where it stands


def planar(pose: Pose, z: float) -> Pose:
    """``pose`` flattened onto the plane at height ``z`` [m]: x, y and yaw kept."""
    yaw = quat.to_euler(pose.orientation)[2]
    return Pose((pose.position[0], pose.position[1], z), quat.from_euler(0.0, 0.0, yaw))


def drive(
    robot: ProjectedRobot,
    target: PoseStamped | PoseLike,
    allowed_links: Collection[str] = (),
    hand: HandContact | None = None,
    for_arm: bool = False,
) -> Pose:
    """Put the robot's base at ``target`` (map unless stamped); return the reached pose.

    ``for_arm``: the drive is an arm motion's (``move_tcp``'s base part), not the plan's
    own: it neither goes back the way out (``robot.ways_out``) nor clears it.

    ``allowed_links`` may touch things on the way (the hand holding a door's handle);
    ``hand`` bounds what they touch and how deep (a drive inside ``move_tcp``): the
    planned drive is walked densely for it, and its trajectory stores the bound.

    Raises:
        NavigationPoseUnreachable: the robot would collide there, or its base is fixed
            (``base_type="fixed"``) and the target is elsewhere; it stays where it was.
    """
    start = robot.base_pose()
    goal = planar(robot.in_map(target), start.position[2])
    if not all(math.isfinite(v) for v in goal.position):
        raise ProjectionError(
            f"navigation target {target!r} has a position that is not finite; give numbers"
        )
    if robot.description.drive == "fixed" and (
        start.distance_to(goal) > FIXED_TOLERANCE or start.angle_to(goal) > FIXED_TOLERANCE
    ):
        raise NavigationPoseUnreachable(
            f"{robot.name}'s base is fixed (base_type='fixed'): it stays where it stands; "
            "stand the robot where it works, or give the base type it has",
            target=target,
        )
    checked = planned_against(robot)  # what the path is planned against
    try:
        try:
            path = plan_base_path(
                robot.handle, goal, seed=robot.motion.seed, allowed_links=allowed_links
            )
        except NavigationPathBlocked:
            if not robot.ways_out or for_arm:  # only the plan's own drives go back
                raise
            _back_the_way_out(robot, allowed_links)
            checked = planned_against(robot)
            path = plan_base_path(
                robot.handle, goal, seed=robot.motion.seed, allowed_links=allowed_links
            )
    except NavigationPoseUnreachable as failure:
        failure.target = target
        raise
    if not for_arm:  # a drive of the plan's own reached its goal: no way out kept
        robot.ways_out.clear()
    trajectory = path.trajectory
    if hand is not None and allowed_links:
        _hand_kept(robot, trajectory, hand, target)
        allowances = (*trajectory.allowed_contacts, *hand.allowances())
        trajectory = replace(trajectory, allowed_contacts=allowances)
    follow(robot, trajectory, checked)
    return goal


def _back_the_way_out(robot: ProjectedRobot, allowed_links: Collection[str]) -> None:
    """Drive back to where the base stood before an arm motion's drive that then found no
    path (``robot.ways_out``): the drafted Stretch, driven 0.13 m and turned 31 degrees
    towards the table's milk, its arm then blocked by the table's top, stood turned in the
    0.65 m between the table and the kitchen's south wall, where no drive found a way out
    (the fridge left open, both spoons on the table). It came from there, so the way back is
    short; asked only when a drive from here found no path, so a base that goes on from
    where it was left (the Stretch's next grasp of a bowl from there) does as before.

    Raises:
        NavigationPathBlocked: no way back either (the base stays).
    """
    (way_out,) = robot.ways_out
    robot.ways_out.clear()
    checked = planned_against(robot)
    back = plan_base_path(
        robot.handle, way_out, seed=robot.motion.seed, allowed_links=allowed_links
    )
    follow(robot, back.trajectory, checked)


def _hand_kept(
    robot: ProjectedRobot, trajectory: JointTrajectory, hand: HandContact, target: object
) -> None:
    """Refuse a drive that takes the hand beyond its contact (:func:`hand_breach`).

    Raises:
        NavigationPathBlocked: names the hand link, what it goes into, how deep and where.
    """
    breach = hand_breach(robot.handle, trajectory, hand, robot.carried)
    if breach is None:
        return
    allowed = (
        f"its bound is {breach.bound * 1000:.0f} mm" if breach.bound else "it may not touch it"
    )
    raise NavigationPathBlocked(
        f"{robot.name}'s drive takes its hand's {breach.link} {breach.depth * 1000:.1f} mm into "
        f"{breach.other} ({allowed}) {breach.time:.2f} s along; the base stays",
        target=target,
        path_fraction=breach.time / trajectory.duration if trajectory.duration > 0 else 0.0,
    )


def unchecked_base_motion(robot: ProjectedRobot, goal: Pose) -> JointTrajectory:
    """The timed base motion to ``goal`` with no check (CRAM's ``allow_all``): straight for
    a holonomic base; else turn, drive along the heading, turn (never sideways)."""
    start = robot.base_pose()
    yaw0 = quat.to_euler(start.orientation)[2]
    turn = quat.to_euler(goal.orientation)[2] - yaw0
    yaw1 = yaw0 + math.atan2(math.sin(turn), math.cos(turn))  # the shorter way round
    ends = [(*start.position[:2], yaw0), (*goal.position[:2], yaw1)]
    if robot.description.drive != "holonomic":
        local = start.inverse() * goal
        motion = BaseMotion(local.position[0], local.position[1], yaw1 - yaw0)
        ends = [_in_map(start, yaw0, step) for step in motion.drive_steps()]
    limits = joint_limits(robot.description, BASE_JOINTS)
    return time_parameterize(robot.name, BASE_JOINTS, ends, limits, kind="base")


def _in_map(
    start: Pose, yaw0: float, step: tuple[float, float, float]
) -> tuple[float, float, float]:
    """A step ``(x, y, yaw)`` of the base's own frame at ``start`` as map x, y, yaw."""
    x, y, yaw = step
    c, s = math.cos(yaw0), math.sin(yaw0)
    return (start.position[0] + c * x - s * y, start.position[1] + s * x + c * y, yaw0 + yaw)


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

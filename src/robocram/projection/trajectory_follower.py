"""Projection follows a timed trajectory: the robot ends where the trajectory ends.

Nothing between the points needs simulating (the path was checked before it was timed),
so following is a walk over the points with a stop point at each: a stop during the
motion leaves the robot, and what it holds, at the point it had reached. Every executed
trajectory, or its part up to a stop, is reported to the motion layer's listeners
(traces, viewers). A trajectory is checked again from the point reached whenever the
world changed meanwhile (:mod:`~robocram.projection.path_watch`).
"""

from __future__ import annotations

from dataclasses import replace

from robocram.execution import checkpoint, current_task
from robocram.motion import (
    BASE_JOINTS,
    BODY_JOINTS,
    JointTrajectory,
    TrajectoryPoint,
    report_executed,
)
from robocram.motion.crouch_path import is_height_and_joints, put_height_and_joints
from robocram.motion.whole_body_scene import is_whole_body, put_base_and_joints
from robocram.projection.path_watch import PathWatch, planned_against
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import BodyStamps


def follow(
    robot: ProjectedRobot, trajectory: JointTrajectory, checked: BodyStamps | None = None
) -> None:
    """Move ``robot`` along ``trajectory``; a stopped task leaves it where it had got to.

    ``checked`` is what the trajectory was planned against (:func:`planned_against` when
    it was planned; default: the world as it stands now). A body changed since that the
    rest of the path would touch stops the robot before it.

    Raises:
        NavigationPathBlocked: a base's or body's path meets a changed body.
        ManipulationPathBlocked: a joint motion meets a changed body.
    """
    points = trajectory.points
    count = len(points)
    task = current_task()  # the same at every point: asked once, its stop point per point
    stop_point = checkpoint if task is None else task.check_stop
    watch = PathWatch(robot, trajectory, checked or planned_against(robot))
    reached = 1
    try:
        while reached < count:
            stop_point()
            blocked = watch.blocked(reached)  # changed since planned, or meanwhile
            if blocked is not None:
                reached = blocked[0]  # the robot gets to the point before
                raise blocked[1]
            reached += 1
    except BaseException:
        part = replace(trajectory, points=points[:reached])
        _apply(robot, trajectory.joint_names, points[max(reached - 1, 0)])
        report_executed(_with_carried(robot, part, trajectory.duration))
        raise
    _apply(robot, trajectory.joint_names, points[-1])
    report_executed(_with_carried(robot, trajectory, trajectory.duration))


def _with_carried(robot: ProjectedRobot, done: JointTrajectory, whole: float) -> JointTrajectory:
    """``done`` (all or the start of a trajectory lasting ``whole`` [s]) with the joints the
    robot moves along: by time, as far as it got; along a link's line, the whole step (the
    joint is wherever the link is on the line, stopped part of the way or not)."""
    if not robot.carried:
        return done
    share = done.duration / whole if whole > 0.0 else 1.0
    carried = tuple(c if c.line else replace(c, end=c.at(share)) for c in robot.carried)
    return replace(done, carried=carried)


def _apply(robot: ProjectedRobot, joints: tuple[str, ...], point: TrajectoryPoint) -> None:
    values = dict(zip(joints, point.positions, strict=True))
    if joints == BODY_JOINTS:  # a flight: the body in map
        turn = quat.from_euler(values["roll"], values["pitch"], values["yaw"])
        robot.world.set_pose(robot.name, Pose((values["x"], values["y"], values["z"]), turn))
        return
    if joints == BASE_JOINTS:  # what the robot holds rides along
        height = robot.base_pose().position[2]
        yaw = quat.from_euler(0.0, 0.0, values["yaw"])
        robot.world.set_pose(robot.name, Pose((values["x"], values["y"], height), yaw))
        return
    if is_whole_body(joints):  # base and arm at once
        put_base_and_joints(robot.handle, values)
        return
    if is_height_and_joints(joints):  # a crouch: the base's height and the legs
        put_height_and_joints(robot.handle, values)
        return
    robot.world.set_joint_states(robot.name, values)

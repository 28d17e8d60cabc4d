"""A held tool along a path in projection: reach its start, follow it, say where it went.

``follow_tool_path`` is the ``move_tool_path`` command of the ``tools`` module: the tool
point's path (poses in ``map``) becomes poses of the arm's tool frame through the grasp
as the world holds it (the tool attached to the hand), the arm moves to the path's
first pose avoiding everything (a joint-space motion, planned round what is in the way),
then follows the rest as a tool path (:func:`~robocram.motion.tool_path.plan_tool_path`),
the named contacts allowed within their depths. An arm that reaches with its base
(``base_in_ik``) and cannot follow the whole path alone follows it with base and arm in
one trajectory (:mod:`~robocram.motion.whole_body_tool_path`). The answer says how far it got and
where the tool point went, read from the world at every executed trajectory point.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from robocram.designators.tool_answers import ToolPathAnswer
from robocram.execution.failures import ToolPathUnreachable
from robocram.kinematics import base_in_ik
from robocram.motion import ContactAllowance, JointTrajectory
from robocram.motion.tool_path import ToolPathMotion, plan_tool_path
from robocram.motion.whole_body_scene import is_whole_body, put_configuration
from robocram.motion.whole_body_tool_path import plan_whole_body_tool_path
from robocram.projection.arm import move_tcp
from robocram.projection.errors import ProjectionError
from robocram.projection.path_watch import planned_against
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.trajectory_follower import follow
from robocram.tf import Pose, PoseLike, PoseStamped

PathPose = PoseStamped | PoseLike


@dataclass(frozen=True)
class ToolGrip:
    """The tool ``arm`` holds (None: the hand itself) and its point in the arm's tool frame."""

    arm: str
    tool: str | None
    point_in_tcp: Pose


def tool_grip(
    robot: ProjectedRobot, arm: str, tool: str | None, tool_point: PoseLike | None
) -> ToolGrip:
    """The grip of ``tool`` (held by ``arm``) and its point ``tool_point`` (in the tool's
    frame; None: its origin) in the arm's tool frame, as the world holds it now.

    Raises:
        ProjectionError: the tool is not held by ``arm``'s hand.
    """
    world = robot.world
    spec = robot.arm(arm)
    point = Pose() if tool_point is None else Pose.coerce(tool_point)
    if tool is None:
        return ToolGrip(arm, None, point)
    held = world.bodies.attachments(robot.name)
    hand = {*spec.hand_links, *spec.gripper_links, spec.tool_frame, spec.end_effector_link}
    if held.get(tool) not in hand:
        raise ProjectionError(
            f"{robot.name}'s {arm} hand does not hold {tool!r} (it holds "
            f"{sorted(o for o, link in held.items() if link in hand) or 'nothing'}); "
            "pick the tool up first"
        )
    tcp_t_tool = world.link_pose(robot.name, spec.tool_frame).inverse() * world.pose(tool)
    return ToolGrip(arm, tool, tcp_t_tool * point)


def allowances(tool: str | None, contacts: object) -> tuple[ContactAllowance, ...]:
    """The named contacts ``[[object, depth], ...]`` of ``tool`` (``none``: no contact).

    Raises:
        ProjectionError: a contact is not ``[name, depth >= 0]``, or names no tool.
    """
    if contacts in (None, "none") or contacts == []:
        return ()
    if tool is None or not isinstance(contacts, list | tuple):
        raise ProjectionError(
            f"tool contacts {contacts!r} need a held tool and a list [[object, depth], ...]"
        )
    found = []
    for item in contacts:
        if not (isinstance(item, list | tuple) and len(item) == 2):
            raise ProjectionError(f"a tool contact is [object, depth [m]], got {item!r}")
        name, depth = item
        if not isinstance(depth, int | float) or not depth >= 0.0:
            raise ProjectionError(f"the depth of {tool!r}'s contact with {name!r} is {depth!r}")
        found.append(ContactAllowance(tool, str(name), float(depth)))
    return tuple(found)


def plan_from_start(
    robot: ProjectedRobot,
    grip: ToolGrip,
    path: Sequence[PathPose],
    contacts: tuple[ContactAllowance, ...] = (),
    needed: float = 0.0,
) -> ToolPathMotion:
    """Move the tool point to the path's first pose (avoiding everything), then plan the
    rest as a tool path from there (nothing of it executed yet).

    Raises:
        ProjectionError: the path is empty.
        ManipulationPoseUnreachable: the path's first pose cannot be reached.
        ToolPathUnreachable: the plan reaches less than ``needed`` of the path (before
            any of it is followed).
    """
    if not path:
        raise ProjectionError(f"the tool path of {robot.name}'s {grip.arm} arm has no poses")
    in_map = [robot.in_map(p) for p in path]
    move_tcp(robot, grip.arm, in_map[0] * grip.point_in_tcp.inverse(), "avoid_all")
    base = robot.base_pose().inverse()
    in_base = [base * p for p in in_map[1:]] or [base * in_map[0]]
    planned = plan_tool_path(
        robot.handle, grip.arm, in_base,
        point_in_tcp=grip.point_in_tcp, contacts=contacts, settings=robot.motion,
    )  # fmt: skip
    if planned.fraction < 1.0 and base_in_ik(robot.description, grip.arm):
        whole = plan_whole_body_tool_path(
            robot.handle, grip.arm, in_base,
            point_in_tcp=grip.point_in_tcp, contacts=contacts, settings=robot.motion,
        )  # fmt: skip
        planned = whole if whole.fraction > planned.fraction else planned
    if planned.fraction < needed:
        raise ToolPathUnreachable(
            f"{robot.name}'s {grip.arm} arm reaches {planned.fraction:.0%} of the tool path "
            f"from where it stands, {needed:.0%} needed ({planned.stopped_by})",
            target=in_map[-1],
            fraction=planned.fraction,
            needed=needed,
            stopped_by=planned.stopped_by,
        )
    return planned


def follow_tool_path(
    robot: ProjectedRobot,
    arm: str,
    path: Sequence[PathPose],
    tool: str | None,
    tool_point: PoseLike | None,
    contacts: object = "none",
    needed: float = 0.0,
) -> ToolPathAnswer:
    """Move ``tool`` (held by ``arm``) so that its point follows ``path``; refused (raised,
    :func:`plan_from_start`) when the plan reaches less than ``needed`` of it."""
    grip = tool_grip(robot, arm, tool, tool_point)
    checked = planned_against(robot)
    planned = plan_from_start(robot, grip, path, allowances(tool, contacts), needed)
    follow(robot, planned.motion.trajectory, checked)
    return answer(robot, grip, planned)


def answer(robot: ProjectedRobot, grip: ToolGrip, planned: ToolPathMotion) -> ToolPathAnswer:
    """What a followed tool path answers: how far, why it stopped, where the point went."""
    poses = tool_poses(robot, grip, planned.motion.trajectory)
    return ToolPathAnswer(planned.fraction, planned.stopped_by, poses)


def tool_poses(
    robot: ProjectedRobot, grip: ToolGrip, trajectory: JointTrajectory
) -> tuple[Pose, ...]:
    """The tool point's pose in ``map`` at every point of ``trajectory`` (the robot is put
    back where it stands after)."""
    world, name = robot.world, robot.name
    frame = robot.arm(grip.arm).tool_frame
    now, pose = world.joint_states(name), world.pose(name)
    found = []
    try:
        for point in trajectory.points:
            put_configuration(robot.handle, trajectory.joint_names, point.positions)
            found.append(world.link_pose(name, frame) * grip.point_in_tcp)
    finally:
        if is_whole_body(trajectory.joint_names):
            world.set_pose(name, pose)
        world.set_joint_states(name, {j: now[j] for j in trajectory.joint_names if j in now})
    return tuple(found)

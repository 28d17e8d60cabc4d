"""A curve of a held tool's point, followed by the arm: a checked, timed tool path.

A tool path (wiping, sawing, stirring, tilting a cup) is a sequence of poses of a point
of the tool the hand holds (the sponge's underside, the knife's edge, the spoon's tip,
the cup's lip), in the robot's root link. The grasp turns each into a pose of the arm's
tool frame (``tcp_T_point``); the curve is cut into steps of at most 2 cm and 0.05 rad of
the tool point, and the arm follows it as a Cartesian tool line follows its line
(:func:`~robocram.motion.cartesian_path.follow_poses`: IK from step to step, every step
and the segment to it checked, a jump ends it). The answer is the path as far as it got,
the fraction reached, and the trajectory, timed under every joint's velocity,
acceleration and jerk limit like any tool line (its gentle corners on checked blends).

The contacts the tool must make are allowed by name and bounded
(:class:`~robocram.motion.contact_allowance.ContactAllowance`: the sponge on the table
5 mm deep at most, the knife in the bread it cuts); every other contact of the tool, the
hand or the arm is a collision. The trajectory stores the allowances, so the audit holds
it to the same bounds.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass, replace

from robocram.motion.arm_motion import ArmMotion, MotionSettings
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.cartesian_path import (
    MAX_ROTATION,
    MAX_STEP,
    follow_poses,
    line_poses,
)
from robocram.motion.configuration_checker import ConfigurationChecker
from robocram.motion.contact_allowance import ContactAllowance
from robocram.motion.corner_blend import blend_radii
from robocram.motion.errors import MotionInputError
from robocram.motion.joint_limits import joint_limits
from robocram.motion.joint_path import JointPath
from robocram.motion.self_path_check import SelfPathCheck
from robocram.motion.time_parameterization import MAX_WAYPOINTS, time_parameterize
from robocram.motion.travel_bound import TravelBound
from robocram.tf import Pose
from robocram.world import RobotHandle

AT_TCP = Pose()  # a tool point at the arm's tool frame itself
DEFAULT_SETTINGS = MotionSettings()
TOOL_PATH_KIND = "tool-path"  # the kind of a tool path's trajectory (traces, audit)


@dataclass(frozen=True)
class ToolPathMotion:
    """A followed tool path: the motion (as far as it got), the fraction of the curve
    reached (0..1) and why it stopped (empty when it reached the end)."""

    motion: ArmMotion
    fraction: float
    stopped_by: str


def densified(poses: Sequence[Pose], max_step: float = MAX_STEP) -> list[Pose]:
    """``poses`` with steps of at most ``max_step`` [m] and :data:`MAX_ROTATION` between
    them (the first pose kept, each given pose kept)."""
    if not poses:
        return []
    out = [poses[0]]
    for a, b in zip(poses, poses[1:], strict=False):
        out += line_poses(a, b, max_step, MAX_ROTATION)
    return out


def plan_tool_path(
    robot: RobotHandle,
    arm: str,
    path_in_base: Sequence[Pose],
    *,
    point_in_tcp: Pose = AT_TCP,
    contacts: Collection[ContactAllowance] = (),
    settings: MotionSettings = DEFAULT_SETTINGS,
) -> ToolPathMotion:
    """Follow the tool point through ``path_in_base`` (poses in the robot's root link,
    from where the tool point is now), as far as it can be followed.

    ``point_in_tcp`` is the tool point in ``arm``'s tool frame (from the grasp); only
    ``contacts`` may be made, each within its depth.

    Raises:
        MotionInputError: the path is empty or has more steps than a trajectory holds.
    """
    world = robot.world
    targets = tool_targets(robot, arm, path_in_base, point_in_tcp, "a tool path")
    desc = robot.description
    joints = tuple(desc.arms[arm].joints)
    current = world.joint_states(robot.name)
    start = [current[j] for j in joints]
    judge = _judge(robot, joints, start, tuple(contacts))
    bound = TravelBound.of(robot, joints)
    line = follow_poses(desc, arm, judge, current, targets, bound, random_seed=settings.seed)
    path, fraction, stopped = cut_apart(robot, line.path, line.fraction, line.stopped_by)
    timed = timed_tool_path(robot, path, fraction, judge, bound, settings, TOOL_PATH_KIND, contacts)
    return ToolPathMotion(timed, fraction, stopped)


def tool_targets(
    robot: RobotHandle, arm: str, path_in_base: Sequence[Pose], point_in_tcp: Pose, what: str
) -> list[Pose]:
    """The tool frame's poses that put the tool point on ``path_in_base`` (the root link),
    in steps of at most :data:`MAX_STEP` and :data:`MAX_ROTATION` from where it is now.

    Raises:
        MotionInputError: the path is empty or has more steps than a trajectory holds.
    """
    world = robot.world
    if not path_in_base:
        raise MotionInputError(
            f"{what} of {robot.name}'s {arm} arm needs at least one pose; got none"
        )
    frame = robot.description.arms[arm].tool_frame
    tcp = world.pose(robot.name).inverse() * world.link_pose(robot.name, frame)
    steps = densified([tcp * point_in_tcp, *path_in_base])[1:]
    if len(steps) > MAX_WAYPOINTS:
        raise MotionInputError(
            f"{what} of {robot.name}'s {arm} arm has {len(steps)} steps of "
            f"{MAX_STEP} m; at most {MAX_WAYPOINTS}: give a shorter path"
        )
    inverse = point_in_tcp.inverse()
    return [pose * inverse for pose in steps]


def timed_tool_path(
    robot: RobotHandle,
    path: JointPath,
    fraction: float,
    checker: ConfigurationChecker,
    bound: TravelBound,
    settings: MotionSettings,
    kind: str,
    allowances: Collection[ContactAllowance],
) -> ArmMotion:
    """``path`` timed under its joints' limits (its corners on checked blends when the
    whole path was reached), storing ``allowances`` for whoever audits it."""
    radii = blend_radii(checker, bound, path.waypoints) if fraction >= 1.0 else None
    limits = joint_limits(robot.description, path.joints)
    trajectory = time_parameterize(
        robot.name, path.joints, path.waypoints, limits, kind=kind, period=settings.period,
        corner_radii=radii,
    )  # fmt: skip
    stored = replace(trajectory, allowed_contacts=(*trajectory.allowed_contacts, *allowances))
    return ArmMotion(path, stored, fraction)


def _judge(
    robot: RobotHandle,
    joints: tuple[str, ...],
    start: list[float],
    contacts: tuple[ContactAllowance, ...],
) -> BulletScene:
    """The world itself as the checker, the named contacts bounded, and the contacts the
    robot already has at the start (beyond those bounds) allowed to end."""
    judge = BulletScene(robot, joints, contacts=contacts)
    touching = judge.colliding(start)
    if touching:
        judge = BulletScene(robot, joints, allowed_pairs=touching, contacts=contacts)
    return judge


def cut_apart(
    robot: RobotHandle,
    path: JointPath,
    fraction: float,
    stopped: str,
    joints: tuple[str, ...] | None = None,
) -> tuple[JointPath, float, str]:
    """The path cut where it would first run the robot into itself. ``joints`` (default
    the path's) are the path's last columns the self walk takes: a whole-body path's base
    columns move the whole robot alike."""
    if len(path.waypoints) < 2:
        return path, fraction, stopped
    joints = path.joints if joints is None else joints
    walked = [w[len(w) - len(joints) :] for w in path.waypoints]
    blocked = SelfPathCheck.of(robot, joints).first_collision(walked)
    if blocked is None:
        return path, fraction, stopped
    where, pairs = blocked
    segments = len(path.waypoints) - 1
    kept = max(int(where * segments), 0)  # whole segments before the first contact
    waypoints = path.waypoints[: kept + 1]
    share = kept / segments
    named = ", ".join(f"{a} hits {b}" for a, b in pairs[:2])
    return (
        replace(path, waypoints=waypoints),
        fraction * share,
        f"the path runs the robot into itself ({named})",
    )

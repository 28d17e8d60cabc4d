"""What the driver does with each kind of goal, on the projected robot of its world.

Each function takes the goal message and a :class:`GoalContext` and returns
``(succeeded, result fields, status text)``; ``None`` means the goal was preempted. They
reuse projection's low-level functions, so a robot behind ROS behaves as in projection.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import partial
from types import SimpleNamespace
from typing import Any

import numpy as np

from robocram.designators import ObjectDesignator
from robocram.execution.failures import GripperClosedCompletely, GripperMetOneSide, PlanFailure
from robocram.projection import ProjectedRobot
from robocram.projection.gripper import grip, gripper_joints, open_gripper, set_gripper
from robocram.projection.navigation import drive
from robocram.projection.neck import look_at
from robocram.projection.perception import visible_matches
from robocram.ros.gripper_semantics import GripperSemantics
from robocram.ros.transport import GoalState, RosDict
from robocram.ros_driver.held_handles import HeldHandles
from robocram.ros_driver.motion import MotionOptions, Stepper, base_motion, joint_motion
from robocram.tf import Pose, PoseStamped, pose_stamped_to_ros

RosMessage = Any  # a genpy message (goal, result, pose): Debian's rospy ships no types
Outcome = tuple[bool, dict[str, Any], str] | None
INVALID_JOINTS = -2
GOAL_TOLERANCE_VIOLATED = -5
NAV2_GOAL_OCCUPIED = 206  # nav2_msgs ComputePathToPose's, passed on by NavigateToPose
NAV2_FAILED_TO_MAKE_PROGRESS = 105  # nav2_msgs FollowPath's
DEFAULT_GOAL_TOLERANCE = 0.01  # [rad | m] for joints whose goal gives 0 (the default)
GRIP_TOLERANCE = 1e-6  # [rad | m] a command this close to the lower limit closes fully


@dataclass
class GoalContext:
    """The robot, its motion options and the stepper watching the goal's preemption.

    ``soft_limits`` (the real PR2's controllers): joint targets are clamped into them
    silently, as its safety controller does, and trajectory results carry no status text.
    ``handles``: the handles the grippers hold (their parts move with the hands).
    ``feedback``: publishes the goal's feedback fields (ROS 2's servers; else ignored).
    """

    robot: ProjectedRobot
    options: MotionOptions
    stepper: Stepper
    soft_limits: dict[str, tuple[float, float]] | None = None
    handles: HeldHandles = field(default_factory=HeldHandles)
    feedback: Callable[[RosDict], None] = lambda _: None


def _soft_clamped(target: dict[str, float], ctx: GoalContext) -> dict[str, float]:
    if ctx.soft_limits is None:
        return target
    limits = ctx.soft_limits
    return {
        j: min(max(v, limits[j][0]), limits[j][1]) if j in limits else v for j, v in target.items()
    }


def _trajectory_outcome(ok: bool, code: int, text: str, ctx: GoalContext) -> Outcome:
    """A trajectory goal's end; the real PR2's controller says it in the result only."""
    status = "" if ctx.soft_limits is not None else text
    return ok, {"error_code": code, "error_string": text}, status


def _pose(msg: RosMessage) -> Pose:
    p, q = msg.position, msg.orientation
    return Pose((p.x, p.y, p.z), (q.x, q.y, q.z, q.w))


def _stamped_in_map(robot: ProjectedRobot, frame: str, pose: Pose) -> Pose:
    return robot.in_map(PoseStamped.from_pose(frame or "map", pose))


def seconds(duration: RosMessage) -> float:
    """A duration message in seconds: ROS 1's (``to_sec``) or ROS 2's (``sec``, ``nanosec``)."""
    if hasattr(duration, "to_sec"):
        return float(duration.to_sec())
    return float(duration.sec) + float(duration.nanosec) * 1e-9


def _drive(
    target: RosMessage, ctx: GoalContext, step_done: Callable[[], None] = lambda: None
) -> tuple[int, str] | None:
    """Drive straight to the stamped pose ``target`` unless the goal is in collision:
    ``(0, text)`` reached, ``(NAV2_GOAL_OCCUPIED | NAV2_FAILED_TO_MAKE_PROGRESS, why)``,
    None if preempted."""
    robot = ctx.robot
    with ctx.stepper.lock:
        in_map = _stamped_in_map(robot, target.header.frame_id, _pose(target.pose))
        start = robot.base_pose()
        try:  # checks the goal for the base, leaves the robot where it was if bad
            drive(robot, in_map, _above_base(robot))
        except PlanFailure as failure:
            return NAV2_GOAL_OCCUPIED, str(failure)
        robot.world.set_pose(robot.name, start)
        duration, step = base_motion(robot, in_map, ctx.options)

    def stepping(fraction: float) -> None:
        step(fraction)
        ctx.handles.follow(robot)  # a drawer held by the hand comes along
        step_done()

    if not ctx.stepper.run(duration, stepping):
        return None
    with ctx.stepper.lock:
        try:
            reached = drive(robot, in_map, _above_base(robot))
            ctx.handles.follow(robot)
        except PlanFailure as failure:  # something moved into the way meanwhile
            return NAV2_FAILED_TO_MAKE_PROGRESS, str(failure)
    return 0, f"reached {reached.position}"


def _above_base(robot: ProjectedRobot) -> set[str]:
    """The links a navigation stack does not see: all but the base's footprint (Nav2 and
    move_base check the base's footprint in their costmaps, not the arms)."""
    model = robot.description.model
    return set(model.links) - set(model.base_links())


def move_base(goal: RosMessage, ctx: GoalContext) -> Outcome:
    """``move_base_msgs/MoveBase``: refuse a goal in collision, else drive straight there."""
    driven = _drive(goal.target_pose, ctx)
    if driven is None:
        return None
    code, text = driven
    return code == 0, {}, text


def navigate_to_pose(goal: RosMessage, ctx: GoalContext) -> Outcome:
    """``nav2_msgs/NavigateToPose``: as ``move_base``; a failure's result carries Nav2's
    error code (the failing planner's or controller's, as bt_navigator passes it on).
    While driving, feedback: the base's pose, the time so far and the distance left."""
    robot, started = ctx.robot, time.monotonic()
    frame, goal_xy = (
        goal.pose.header.frame_id,
        (goal.pose.pose.position.x, goal.pose.pose.position.y),
    )

    def feedback() -> None:  # under the stepper's lock
        here = robot.base_pose()
        elapsed = time.monotonic() - started
        ctx.feedback(
            {
                "current_pose": pose_stamped_to_ros(PoseStamped.from_pose(frame or "map", here)),
                "navigation_time": {"secs": int(elapsed), "nsecs": int(elapsed % 1 * 1e9)},
                "distance_remaining": math.dist(here.position[:2], goal_xy),
            }
        )

    driven = _drive(goal.pose, ctx, feedback)
    if driven is None:
        return None
    code, text = driven
    return code == 0, {"error_code": code, "error_msg": "" if code == 0 else text}, text


def follow_joint_trajectory(goal: RosMessage, ctx: GoalContext) -> Outcome:
    """``control_msgs/FollowJointTrajectory``: play every point at its time, then check the
    joints against the last point within the goal's tolerances, as a controller does.

    Bad joint names or no points are ``INVALID_JOINTS``; a point outside the joint limits
    (clamped) or a joint stopping beyond its goal tolerance is ``GOAL_TOLERANCE_VIOLATED``.
    """
    names = list(goal.trajectory.joint_names)
    with ctx.stepper.lock:
        known = ctx.robot.world.joint_states(ctx.robot.name)
    unknown = [n for n in names if n not in known]
    if unknown or not goal.trajectory.points:
        text = f"unknown joints {unknown}" if unknown else "the trajectory has no points"
        return False, {"error_code": INVALID_JOINTS, "error_string": text}, text
    elapsed = 0.0
    for point in goal.trajectory.points:
        target = _soft_clamped(dict(zip(names, map(float, point.positions), strict=True)), ctx)
        at = seconds(point.time_from_start)
        span, elapsed = at - elapsed, at
        with ctx.stepper.lock:
            duration, step = joint_motion(ctx.robot, target, span, ctx.options)
        if not ctx.stepper.run(duration, partial(_pulling, step, ctx)):
            return None
        with ctx.stepper.lock:
            clamped = ctx.robot.world.set_joint_states(ctx.robot.name, target)
            ctx.handles.follow(ctx.robot)
        if clamped:
            text = "joint goals outside the limits, clamped: " + ", ".join(
                f"{c.name}={c.requested} not in [{c.lower}, {c.upper}]" for c in clamped
            )
            return _trajectory_outcome(False, GOAL_TOLERANCE_VIOLATED, text, ctx)
    return _at_goal(goal, names, ctx)


def _pulling(step: Callable[[float], None], ctx: GoalContext, fraction: float) -> None:
    """A trajectory step; the parts whose handles the hands hold follow them."""
    step(fraction)
    ctx.handles.follow(ctx.robot)


def single_joint_position(goal: RosMessage, ctx: GoalContext, joint: str) -> Outcome:
    """``pr2_controllers_msgs/SingleJointPosition`` (the PR2's torso): move ``joint`` to the
    position over ``min_duration``; the result has no fields, the status text says more."""
    target = _soft_clamped({joint: float(goal.position)}, ctx)
    with ctx.stepper.lock:
        duration, step = joint_motion(ctx.robot, target, seconds(goal.min_duration), ctx.options)
    if not ctx.stepper.run(duration, step):
        return None
    with ctx.stepper.lock:
        clamped = ctx.robot.world.set_joint_states(ctx.robot.name, target)
        reached = ctx.robot.world.joint_states(ctx.robot.name)[joint]
    if clamped:
        return False, {}, f"{joint}={goal.position} outside the limits; stopped at {reached}"
    return True, {}, f"{joint} at {reached:.4f}"


def _at_goal(goal: RosMessage, names: list[str], ctx: GoalContext) -> Outcome:
    """Compare the joints with the last point within each joint's goal tolerance (the
    PR2's native JointTrajectory goal has none: each joint gets the default)."""
    last = dict(zip(names, map(float, goal.trajectory.points[-1].positions), strict=True))
    given = getattr(goal, "goal_tolerance", [])
    tolerances = {t.name: float(t.position) for t in given}
    with ctx.stepper.lock:
        reached = ctx.robot.world.joint_states(ctx.robot.name)
    errors = {j: abs(reached[j] - last[j]) for j in names}
    beyond = {
        j: (error, tolerance)
        for j, error in errors.items()
        if (tolerance := _tolerance(tolerances.get(j, 0.0))) is not None and error > tolerance
    }
    worst = max(errors, key=errors.__getitem__)
    if beyond:
        text = "joints beyond their goal tolerance (error, tolerance): " + ", ".join(
            f"{j}=({e:.4f}, {t})" for j, (e, t) in beyond.items()
        )
        return _trajectory_outcome(False, GOAL_TOLERANCE_VIOLATED, text, ctx)
    text = (
        f"reached the last of {len(goal.trajectory.points)} points "
        f"({seconds(goal.trajectory.points[-1].time_from_start):.3f} s); "
        f"largest error {errors[worst]:.2e} ({worst})"
    )
    return _trajectory_outcome(True, 0, text, ctx)


def aborted_on_purpose(action_type: str, bare: bool) -> Outcome:
    """The outcome of ``fault="abort"``: a status text, or (``bare``, as the real PR2's
    trajectory controllers) only a trajectory result's error code and string."""
    text = "the driver aborts every goal (fault='abort')"
    if bare and action_type == "control_msgs/FollowJointTrajectory":
        return False, {"error_code": GOAL_TOLERANCE_VIOLATED, "error_string": text}, ""
    return False, {}, text


def _tolerance(value: float) -> float | None:
    """A goal tolerance as control_msgs means it: 0 the default, negative none."""
    if value < 0.0:
        return None
    return value if value > 0.0 else DEFAULT_GOAL_TOLERANCE


def point_head(goal: RosMessage, ctx: GoalContext) -> Outcome:
    """``control_msgs/PointHead``: aim the camera at the target point."""
    point = goal.target.point
    with ctx.stepper.lock:
        robot = ctx.robot
        target = _stamped_in_map(
            robot, goal.target.header.frame_id, Pose((point.x, point.y, point.z))
        )
        try:
            look_at(robot, target.position)
        except PlanFailure as failure:
            return False, {}, str(failure)
        camera = robot.world.view.camera(robot.name).pose.matrix()
    wanted = np.subtract(target.position, camera[:3, 3])
    cos = float(camera[:3, 2] @ wanted) / max(float(np.linalg.norm(wanted)), 1e-9)
    error = math.acos(max(-1.0, min(1.0, cos)))  # [rad]
    return True, {"pointing_angle_error": error}, f"pointing angle error {error:.4f} rad"


def gripper_command(goal: RosMessage, ctx: GoalContext, semantics: GripperSemantics) -> Outcome:
    """``control_msgs/GripperCommand`` on a gripper as the robot's ROS facts describe it.

    The command maps to the gripper joint by ``semantics`` (a PR2 gap in metres, else the
    joint value). Closing fully grips: with an object between the fingers they stop on it
    (``stalled``), it is held, and the goal ends as the facts say holding ends (the PR2:
    ABORTED); opening lets go. The result's position is in the command's unit.
    """
    robot, arm = ctx.robot, semantics.arm
    position = semantics.joint_value(float(goal.command.position))
    with ctx.stepper.lock:
        joint = gripper_joints(robot, arm)[0]
        limits = robot.world.bodies.joint_limits(robot.name, joint)
        stalled = False
        try:
            if position <= limits.lower + GRIP_TOLERANCE:
                stalled = bool(_grip_pushing(robot, arm))
            elif position >= limits.upper - GRIP_TOLERANCE:
                ctx.handles.release(robot, arm)
                open_gripper(robot, arm)
            else:
                set_gripper(robot, arm, position)
        except GripperClosedCompletely:  # on nothing movable; a handle's bar is thin
            ctx.handles.grasp(robot, arm)
        except PlanFailure as failure:
            return False, {}, str(failure)
        reached = robot.world.joint_states(robot.name)[joint]
    effort = float(goal.command.max_effort) if stalled else 0.0
    result = {
        "position": semantics.command(reached),
        "effort": effort,
        "stalled": stalled,
        "reached_goal": abs(reached - position) < 1e-3,
    }
    succeeded = not (stalled and semantics.holding_status is GoalState.ABORTED)
    return succeeded, result, "holding an object" if stalled else ""


def _grip_pushing(robot: ProjectedRobot, arm: str) -> str:
    """Close the gripper on what is between its fingers; return what it holds. A finger
    that meets a light object first pushes it towards the other, as on a real robot: the
    object slides by the hand's centring shift, where nothing is in its way, and is held.

    Raises:
        GripperMetOneSide: the object cannot slide there (it would hit something).
        GripperClosedCompletely: nothing between the fingers.
    """
    try:
        return grip(robot, arm)
    except GripperMetOneSide as one_sided:
        if one_sided.shift is None or one_sided.met is None:
            raise
        world, met = robot.world, one_sided.met
        before = world.pose(met)
        (x, y, z), (dx, dy, dz) = before.position, one_sided.shift
        world.set_pose(met, Pose((x - dx, y - dy, z - dz), before.orientation))
        hit = [o.name for o in world.contacts.collisions(met) if o.name != robot.name]
        if hit:
            world.set_pose(met, before)
            raise
        try:
            return grip(robot, arm)
        except PlanFailure:
            world.set_pose(met, before)
            raise one_sided from None


def detect_objects(goal: RosMessage, ctx: GoalContext) -> Outcome:
    """``robocram_msgs/DetectObjects``: the visible objects matching type and name."""
    wanted = {k: v for k, v in (("type", goal.object_type), ("name", goal.object_name)) if v}
    robot = ctx.robot
    with ctx.stepper.lock:
        seen = visible_matches(robot, ObjectDesignator(**wanted))
        objects = [
            {
                "name": obj.name,
                "type": obj.type,
                "pose": pose_stamped_to_ros(
                    PoseStamped.from_pose(robot.base_frame, robot.in_base(robot.world.pose(obj)))
                ),
            }
            for obj in seen
        ]
    return True, {"objects": objects}, f"{len(objects)} objects seen"


def parallel_gripper_command(
    goal: RosMessage, ctx: GoalContext, semantics: GripperSemantics
) -> Outcome:
    """``control_msgs/ParallelGripperCommand`` (ros2_controllers' parallel gripper): the
    command's first position, as ``gripper_command`` runs it; the result's ``state`` is a
    JointState of the gripper joint."""
    efforts = list(goal.command.effort)
    command = SimpleNamespace(position=goal.command.position[0], max_effort=(efforts or [0.0])[0])
    outcome = gripper_command(SimpleNamespace(command=command), ctx, semantics)
    if outcome is None:
        return None
    succeeded, result, text = outcome
    if "position" not in result:  # failed before moving: no state to report
        return outcome
    joint = gripper_joints(ctx.robot, semantics.arm)[0]
    state = {"name": [joint], "position": [result["position"]], "effort": [result["effort"]]}
    fields = {"state": state, "stalled": result["stalled"], "reached_goal": result["reached_goal"]}
    return succeeded, fields, text

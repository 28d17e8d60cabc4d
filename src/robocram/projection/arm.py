"""Arms in projection: move the tool frame by IK, or move the arm joints to given values.

``move_tcp`` transforms the target into the robot's root link and solves IK seeded with
the current joints, first with the torso held, then (as CRAM's projection resamples the
torso) with the torso free, rejecting solutions that collide as the motion's collision
mode says (``collision_mode.py``). An arm with fewer than six joints (the HSR's) then
reaches with the base too, as CRAM does for the HSR: a solution with a base part moves the
base first, the way driving does (what the robot holds rides along), then the arm. The
reached tool pose is checked against the target within 1 cm / 0.05 rad, so a silent miss
is impossible.

IK is bounded by counted descents and seeded (``IK_RANDOM_SEED`` unless the caller gives
one), so a projection gives bit-identical joints on an idle and a loaded machine.
"""

from __future__ import annotations

import contextlib
from dataclasses import replace

import numpy as np

from robocram.execution import checkpoint
from robocram.execution.failures import (
    ManipulationGoalNotReached,
    ManipulationPathBlocked,
    NavigationLowLevelFailure,
)
from robocram.kinematics import (
    BaseMotion,
    IKOptions,
    IKResult,
    PlanarBase,
    arm_joints,
    base_in_ik,
    forward_kinematics,
    solve_ik,
)
from robocram.kinematics.planar_base import BASE_X_JOINT, BASE_Y_JOINT, BASE_YAW_JOINT
from robocram.motion import ArmMotion, MotionSettings, plan_arm_motion, plan_tool_line
from robocram.motion.hand_contact import HandContact
from robocram.motion.joint_goal import finite_goal
from robocram.motion.reach_failure import unreachable
from robocram.motion.tool_goal import (
    IK_RANDOM_SEED,
    ensure_reached,
    joint_values,
)
from robocram.motion.whole_body_tool_path import plan_whole_body_tool_path
from robocram.projection.arm_ways import ArmWay
from robocram.projection.certain_miss import CertainMiss, CertainMissJudge, rigid_links
from robocram.projection.collision_mode import (
    allowed_links,
    collision_check,
    hand_contact,
    judged,
    known_mode,
    putting_back_once,
)
from robocram.projection.errors import unknown_name
from robocram.projection.navigation import drive, moved_base, unchecked_base_motion
from robocram.projection.path_watch import planned_against
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.trajectory_follower import follow
from robocram.tf import Pose, PoseLike, PoseStamped

IK_RESTARTS = 100  # descents after the first in each IK query of a move_tcp
BASE_TRAVEL = PlanarBase()  # how far IK may move the base: +-0.5 m in x and y, +-pi in yaw
OFF_LINE = 0.003  # [m] an arm moved ahead of its base keeps the tool this near a carried line
IKQuery = tuple[bool, PlanarBase | None]  # use_torso, base travel (None: the base stays)


def _attempts(
    robot: ProjectedRobot, arm: str, move_base: bool | None, travel: PlanarBase = BASE_TRAVEL
) -> list[IKQuery]:
    """(use_torso, base) of each IK query, in order: the arm, the torso, the base.

    The base solver tries the arm and torso alone first, from the current joints, so with
    the base there is one query.
    """
    desc = robot.description
    torso = desc.torso_joint is not None
    if base_in_ik(desc, arm) if move_base is None else move_base:
        return [(torso, travel)]
    return [(False, None), (True, None)] if torso else [(False, None)]


def _solve(
    robot: ProjectedRobot,
    arm: str,
    target_in_base: Pose,
    mode: str,
    random_seed: int,
    move_base: bool | None = None,
    max_restarts: int = IK_RESTARTS,
    base_travel: PlanarBase = BASE_TRAVEL,
    touching: str | None = None,
    explain: bool = True,
) -> IKResult:
    check = collision_check(robot, arm, mode, touching)
    seed = robot.world.joint_states(robot.name)
    result = IKResult(False)
    attempts = _attempts(robot, arm, move_base, base_travel)
    with robot.ik_lock, putting_back_once(check):  # the robot stands as before after
        for k, (use_torso, base) in enumerate(attempts):
            options = IKOptions(
                use_torso=use_torso, base=base, max_restarts=max_restarts, random_seed=random_seed
            )
            # only the last query's failure is read (if at all): another may stop once sure
            last = k == len(attempts) - 1
            judge = None if last and explain else _judge(robot, arm, mode, touching, options)
            try:
                with contextlib.nullcontext() if judge is None else judged(check, judge):
                    result = solve_ik(
                        robot.description,
                        arm,
                        target_in_base,
                        seed=seed,
                        options=options,
                        collision_check=check,
                        stop_check=checkpoint,  # a stopped task ends the search within a descent
                    )
            except CertainMiss:
                if last:
                    raise
                continue
            if result.success:
                break
    return result


def _judge(
    robot: ProjectedRobot, arm: str, mode: str, touching: str | None, options: IKOptions
) -> CertainMissJudge:
    """What stops the query of ``options`` once a refused solution shows none can be free."""
    desc = robot.description
    tool = options.frame or robot.arm(arm).tool_frame
    moving = arm_joints(desc, arm, options.use_torso)
    hand = hand_contact(robot, arm, mode, touching)
    return CertainMissJudge(
        robot, tool, rigid_links(desc.model, tool, moving), hand,
        options.position_tolerance, options.orientation_tolerance,
    )  # fmt: skip


def move_tcp(
    robot: ProjectedRobot,
    arm: str,
    target: PoseStamped | PoseLike,
    collision_mode: str = "avoid_all",
    random_seed: int = IK_RANDOM_SEED,
    move_base: bool | None = None,
    max_restarts: int = IK_RESTARTS,
    base_travel: PlanarBase = BASE_TRAVEL,
    touching: str | None = None,
    explain: bool = True,
) -> Pose:
    """Put ``arm``'s tool frame at ``target`` (map unless stamped); return it in ``map``.

    ``collision_mode`` is CRAM's: ``avoid_all``, ``allow_hand`` (grasping) or ``allow_all``.
    Under ``allow_hand`` the hand may touch only ``touching`` (an object, or
    ``object/link`` for a handle; None: any object), at most
    :data:`~robocram.motion.hand_contact.HAND_CONTACT_DEPTH` deep.
    ``random_seed`` seeds IK's restarts: the same world, target and seed give the same joints.
    ``move_base``: whether IK may move the base (within :data:`BASE_TRAVEL`) when the arm
    alone cannot reach; None lets the description decide (``kinematics.base_in_ik``). A
    solution with a base part drives the base first, then moves the arm. ``max_restarts``
    bounds each IK query (a best-effort motion may ask for fewer); ``base_travel`` how
    far IK may move the base (a door's arc followed step by step needs little).
    ``explain`` False: the caller reads only that the move failed, not why, so a query
    sure to fail (:mod:`~robocram.projection.certain_miss`) stops at its first refused
    solution and the failure names that solution's one pair.

    Raises:
        ManipulationPoseUnreachable: IK found no collision-free solution; the arm stays.
            The message names the colliding link pairs and advises what applies
            (``reach_failure``); with ``explain`` False it may be a ``CertainMiss``.
        ManipulationGoalNotReached: the applied joints miss the target (limits clamped).
    """
    spec = robot.arm(arm)
    target_in_map = robot.in_map(target)
    target_in_base = robot.base_pose().inverse() * target_in_map
    checked = planned_against(robot)  # what IK and the motion are planned against
    result = _solve(
        robot, arm, target_in_base, collision_mode, random_seed, move_base, max_restarts,
        base_travel, touching, explain,
    )  # fmt: skip
    if not result.success:
        desc = robot.description
        raise unreachable(desc, arm, target, target_in_map, collision_mode, result)
    motion = result.base_motion
    hand = hand_contact(robot, arm, collision_mode, touching)
    drove_from: Pose | None = None  # where the base stood before it drove for the arm
    if motion is not None and motion != BaseMotion():
        goal = moved_base(robot, motion)
        start = robot.base_pose()
        if _arm_then_base(robot, arm, result, goal, collision_mode, hand, target_in_base):
            reached = robot.world.link_pose(robot.name, spec.tool_frame)
            return ensure_reached(robot.name, arm, reached, target, target_in_map)
        target_in_base = robot.base_pose().inverse() * target_in_map
        drove_from = start
    try:
        arm_motion = _arm_motion(robot, arm, result, target_in_base, collision_mode, hand)
    except ManipulationPathBlocked:
        differential = robot.description.drive == "differential"
        if drove_from is not None and differential and not robot.ways_out:  # the first:
            robot.ways_out.append(drove_from)  # where the plan's own drive left it
        raise
    follow(robot, arm_motion.trajectory, checked)
    robot.arm_ways.remember(arm, robot.base_pose(), arm_motion.path)
    reached = robot.world.link_pose(robot.name, spec.tool_frame)
    return ensure_reached(robot.name, arm, reached, target, target_in_map)


def _arm_then_base(
    robot: ProjectedRobot,
    arm: str,
    result: IKResult,
    base_goal: Pose,
    mode: str,
    hand: HandContact | None,
    target_in_base: Pose,
) -> bool:
    """Move the base for a solution that needs it. An arm that reaches with its base
    (``base_in_ik``: the HSR's) turning a part (a door's step) moves base and arm
    together, the tool straight along the step (:func:`_whole_body_step`: the part goes
    where the tool goes, on that line, all the way). Otherwise, or where that fails:
    first the base with the arm as it is (False:
    the arm moves after it); if the arm as it is does not fit there (over a table), the
    arm first, then the base (True: both done). Each motion is checked on its own (the
    drive lets the hand's links touch, the arm's motion bounds them by ``hand``). While
    the hand carries a part, the arm goes first only where it keeps the tool near the
    step's line (:func:`_keeps_to_lines`): an arm moved to where it would be once the base
    has moved took the tool off it, the fingers 12-15 mm into the handle (the drafted
    Fetch's fridge door); else base and arm together, then a shorter step.

    Raises:
        NavigationLowLevelFailure: neither order works (the base's failure).
    """
    if mode.replace("-", "_") == "allow_all":  # nothing checked, the base neither
        follow(robot, unchecked_base_motion(robot, base_goal))
        return False
    whole_first = base_in_ik(robot.description, arm) and _turning_part(robot)
    if whole_first and _whole_body_step(robot, arm, target_in_base, mode, hand, result):
        return True
    free = allowed_links(robot, arm, mode)
    try:
        drive(robot, base_goal, free, hand, for_arm=True)
        return False
    except NavigationLowLevelFailure as failure:
        first = failure
    if robot.carried and not _keeps_to_lines(robot, arm, result):
        # the hand moves a part: the arm ahead of its base would leave it behind
        if not whole_first and _whole_body_step(robot, arm, target_in_base, mode, hand, result):
            return True
        raise first
    checked = planned_against(robot)
    try:
        settings = replace(robot.motion, check=mode.replace("-", "_") != "allow_all")
        motion = plan_arm_motion(
            robot.handle, dict(result.joint_positions),
            settings=settings, hand=hand,
        )  # fmt: skip
    except ManipulationPathBlocked:
        raise first from None
    follow(robot, motion.trajectory, checked)
    try:
        drive(robot, base_goal, free, hand, for_arm=True)
    except NavigationLowLevelFailure:
        raise first from None
    return True


def _turning_part(robot: ProjectedRobot) -> bool:
    """Whether the hand turns a part about a joint on this step (a door, not a drawer):
    its link's orientation differs between the step's ends. Drawers keep their old order
    (base first), which their stands and looks were tuned to: whole-body steps first let
    the HSR's base back off further, where it no longer saw the bowl in the drawer."""
    world = robot.world
    for carried in robot.carried:
        body = world.object(carried.obj)
        index = body.joint_index[carried.joint]
        link = next(name for name, i in body.link_index.items() if i == index)
        now = world.joint_states(carried.obj)[carried.joint]
        there = world.link_pose(carried.obj, link).orientation
        world.set_joint_states(carried.obj, {carried.joint: carried.start})
        here = world.link_pose(carried.obj, link).orientation
        world.set_joint_states(carried.obj, {carried.joint: now})
        if abs(abs(float(np.dot(here, there))) - 1.0) > 1e-12:
            return True
    return False


def _whole_body_step(
    robot: ProjectedRobot,
    arm: str,
    target_in_base: Pose,
    mode: str,
    hand: HandContact | None,
    result: IKResult,
) -> bool:
    """Move base and arm at once, the tool straight to ``target_in_base`` (the root link
    where the base stands): a part the hand carries stays on the tool's line all the way.
    Base and arm share the motion as IK's checked solution ``result`` does (else as the
    least motion of all joints gives). False (nothing moved) when the line cannot be
    followed whole either way, or the base is fixed."""
    motion = result.base_motion
    if robot.description.drive == "fixed" or motion is None:
        return False
    checked = planned_against(robot)
    goal = {BASE_X_JOINT: motion.x, BASE_Y_JOINT: motion.y, BASE_YAW_JOINT: motion.yaw}
    for toward in ({**goal, **result.joint_positions}, None):
        planned = plan_whole_body_tool_path(
            robot.handle, arm, [target_in_base], settings=robot.motion, hand=hand,
            allowed_links=allowed_links(robot, arm, mode), kind="arm", goal=toward,
            carried=robot.carried, keep_touching=False,
        )  # fmt: skip
        if planned.fraction >= 1.0:
            follow(robot, planned.motion.trajectory, checked)
            return True
    return False


def _keeps_to_lines(robot: ProjectedRobot, arm: str, result: IKResult) -> bool:
    """Whether ``arm``'s tool, moved to ``result``'s joints with the base where it stands,
    stays within :data:`OFF_LINE` of every carried part's line (the part follows the tool
    along it: off it, the hand is no longer where the part's handle is)."""
    model = robot.description.model
    now = robot.world.joint_states(robot.name)
    joints = {j: v for j, v in now.items() if model.joints[j].mimic is None}
    joints.update(result.joint_positions)
    tool = forward_kinematics(robot.description, joints, robot.arm(arm).tool_frame)
    at = np.asarray((robot.base_pose() * tool).position)
    for carried in robot.carried:
        if carried.line is None:
            continue
        begin, end = np.asarray(carried.line[0]), np.asarray(carried.line[1])
        way = end - begin
        share = float(np.clip((at - begin) @ way / max(float(way @ way), 1e-12), 0.0, 1.0))
        if float(np.linalg.norm(begin + way * share - at)) > OFF_LINE:
            return False
    return True


def _arm_motion(
    robot: ProjectedRobot,
    arm: str,
    result: IKResult,
    target_in_base: Pose,
    mode: str,
    hand: HandContact | None,
) -> ArmMotion:
    """The checked, timed motion to IK's answer: a straight tool line for ``allow_hand``
    motions (approach, lift, put, retreat) when the whole line can be followed, else a
    joint-space path (straight, or planned round what is in the way). Either way the
    ``hand`` may touch only what it acts on, within its bound."""
    settings = robot.motion
    mode = mode.replace("-", "_")
    if mode == "allow_all":
        settings = replace(settings, check=False)
    goal = dict(result.joint_positions)
    what = f"{robot.name}'s {arm} arm"
    if mode == "allow_hand" and robot.description.torso_joint not in goal:
        line = plan_tool_line(robot.handle, arm, target_in_base, settings=settings, hand=hand)
        if line.fraction >= 1.0:
            return line
    try:
        return plan_arm_motion(robot.handle, goal, settings=settings, what=what, hand=hand)
    except ManipulationPathBlocked as failure:
        failure.arm = arm
        failure.target = target_in_base
        raise


def move_joints(
    robot: ProjectedRobot,
    arm: str,
    configuration: object,
    collision_mode: str = "avoid_all",
    touching: str | None = None,
) -> dict[str, float]:
    """Set ``arm``'s joints from a mapping or ``[[joint, value], ...]``; return what was set.

    The way there is checked in ``collision_mode`` as :func:`move_tcp`'s is: under
    ``allow_hand`` the hand may touch ``touching`` (None: any object) no deeper than
    :data:`~robocram.motion.hand_contact.HAND_CONTACT_DEPTH`, as a hand that let go low
    in a drawer, its fingers at the counter's top, goes back through the joints it came
    in by; ``allow_all`` checks nothing.

    Where the way there is blocked under ``allow_hand`` and the arm's newest kept way
    ran from the goal to here (:mod:`~robocram.projection.arm_ways`), the arm goes back
    along it, each straight segment checked in the mode as it comes (a blocked one
    leaves the arm at the waypoint before it).

    Raises:
        ProjectionError: ``collision_mode`` is none of CRAM's modes, or a joint is not
            the arm's; nothing moved.
        ManipulationGoalNotReached: a value was outside its limits (the arm moves to the
            clamped one).
        ManipulationPathBlocked: no collision-free way there was found; the arm did not move.
    """
    mode = known_mode(arm, collision_mode)
    spec = robot.arm(arm)
    values = joint_values(configuration)
    allowed = set(spec.joints)
    for joint in values:
        if joint not in allowed:
            raise unknown_name("joint", joint, f"{robot.name}'s {arm} arm", allowed)
    limits = {j: robot.world.bodies.joint_limits(robot.name, j) for j in values}
    values = {j: finite_goal(j, v) for j, v in values.items()}  # inf is no limit to move to
    inside = {j: limits[j].clamp(v) for j, v in values.items()}  # moved to, then failed
    what = f"{robot.name}'s {arm} arm"
    checked = planned_against(robot)
    settings = replace(robot.motion, check=False) if mode == "allow_all" else robot.motion
    hand = hand_contact(robot, arm, mode, touching)
    try:
        motion = plan_arm_motion(robot.handle, inside, settings=settings, what=what, hand=hand)
    except ManipulationPathBlocked:
        now, base = robot.world.joint_states(robot.name), robot.base_pose()
        way = robot.arm_ways.back(arm, inside, now, base) if mode == "allow_hand" else None
        if way is None:
            raise
        _go_back(robot, way, settings, what, hand)
    else:
        follow(robot, motion.trajectory, checked)
        robot.arm_ways.remember(arm, robot.base_pose(), motion.path)
    now = robot.world.joint_states(robot.name)
    reached = {j: now[j] for j in values}
    if inside != values:
        culprits = {
            j: (float(v), limits[j].lower, limits[j].upper)
            for j, v in values.items()
            if inside[j] != v
        }
        raise ManipulationGoalNotReached(
            f"joint goals (value, lower, upper) {culprits} of {robot.name}'s {arm} arm are "
            "outside the limits; clamped values applied",
            arm=arm,
            target=values,
            reached=reached,
        )
    return reached


def _go_back(
    robot: ProjectedRobot,
    way: ArmWay,
    settings: MotionSettings,
    what: str,
    hand: HandContact | None,
) -> None:
    """Move the arm back along ``way``, waypoint by waypoint: each straight segment
    checked on the world as it stands when the arm gets there (the hand within its bound).

    Raises:
        ManipulationPathBlocked: a segment is blocked; the arm stays at the waypoint before.
    """
    straight = replace(settings, plan=False)
    for waypoint in way.back():
        checked = planned_against(robot)
        goal = dict(zip(way.joints, waypoint, strict=True))
        motion = plan_arm_motion(robot.handle, goal, settings=straight, what=what, hand=hand)
        follow(robot, motion.trajectory, checked)

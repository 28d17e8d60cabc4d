"""Opening and closing articulated parts (drawers, doors) with an arm of a robot behind ROS.

As in projection (``projection/articulation.py``) the hand takes the handle from the front
(then, when no roll holds it so, from above) and the tool stays on the handle while the
part's joint moves. Over ROS that is a series of goals: open the gripper, the tool before
the handle and onto it (the arm's ``move_tcp``), close the gripper, then *one* arm
trajectory through the IK solutions that keep the tool on the handle at each step of the
joint (planned in the world given to ``ros_robot``, arm only: the base stays where the
plan put it), open the gripper and back off. The robot side moves the part with the hand
(a real drawer follows the hand pulling it; our driver does so kinematically); the part's
joint is then read back from its joint states (``world_mirror.py``) and checked against
the goal.

It needs that world: the handle's pose and how it moves with the joint are read there.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np

from robocram.execution.failures import (
    EnvironmentManipulationImpossible,
    GripperGoalNotReached,
    ManipulationGoalNotReached,
    ManipulationPathBlocked,
    ManipulationPoseUnreachable,
    NavigationGoalNotReached,
    NavigationPathBlocked,
    NavigationPoseUnreachable,
    TorsoGoalNotReached,
)
from robocram.grasping import approach_axis
from robocram.kinematics import IKOptions, PlanarBase, base_in_ik, solve_ik
from robocram.motion import JointTrajectory, joint_limits, time_parameterize
from robocram.motion.part_path import (
    BACK_OFF,
    PITCHES,
    PRE_GRASP,
    ROLLS,
    from_above,
    grasp_in_handle,
    part_path,
)
from robocram.motion.tool_goal import IK_RANDOM_SEED
from robocram.ros.errors import RosCommandError
from robocram.ros.goal_runner import FailureFactory
from robocram.ros.gripper_goal import move_gripper
from robocram.ros.ros_robot_client import RosRobotClient
from robocram.tf import Pose
from robocram.world import World

TORSO_MOVE = 1e-4  # [m] smaller torso changes are not sent
PART_TOLERANCE = 0.01  # [m | rad] the part's joint ends this close to the goal
MAX_JUMP = 0.5  # [rad | m] an IK step moving a joint further is a flip, not a follow
_RANDOM_SEED = IKOptions(random_seed=IK_RANDOM_SEED)  # following the handle, arm alone
_TORSO = IKOptions(use_torso=True)  # a torso height from which the arm reaches
REACHING = (ManipulationPoseUnreachable, ManipulationPathBlocked, ManipulationGoalNotReached)
DRIVING = (NavigationPathBlocked, NavigationPoseUnreachable, NavigationGoalNotReached)
HANDLE = None  # what the hand touches at a handle: anything, unbounded (projection bounds it;
# over ROS the PR2's approach onto a drawer's handle grazes it deeper, see docs/motion.md)
STEP_TRAVEL = PlanarBase(0.15, 0.15, 0.5)  # [m, m, rad] the base's move per step, as projection


class ToolMover(Protocol):
    """What moves a tool frame to a pose in map (the ROS arms' process module)."""

    def move_tcp(
        self,
        arm: str,
        target: Pose,
        collision_mode: str = "avoid_all",
        touching: str | None = "none",
        base_travel: PlanarBase = ...,
    ) -> Pose: ...


def move_part(
    client: RosRobotClient,
    tools: ToolMover,
    arm: str,
    part: str,
    joint: str,
    handle: str,
    goal: float,
) -> float:
    """Hold ``handle`` with ``arm`` and move ``joint`` of ``part`` to ``goal`` [m | rad];
    return the joint value the robot side reports afterwards.

    Raises:
        RosCommandError: no world was given, or ``goal`` is outside the joint's limits.
        EnvironmentManipulationImpossible: no grasp roll lets the arm hold the handle all
            the way (nothing of the path was sent), or the part did not end at the goal.
    """
    world = _world(client, part, joint, goal)
    client.mirror_state()
    start = world.joint_states(part)[joint]
    axis = np.asarray(approach_axis(client.desc, arm))
    action = "opening" if goal > start else "closing"
    failures: list[str] = []
    follow = _with_base_steps if base_in_ik(client.desc, arm) else _with_grasp
    for pitch, roll in ((p, r) for p in (0.0, *PITCHES) for r in ROLLS):
        turn = from_above(Pose(), pitch) if pitch else None
        grasp = grasp_in_handle(axis, roll)
        why = follow(client, tools, arm, (part, joint, handle), grasp, goal, turn)
        if why is not None:
            above = f", from above {pitch:.2f} rad down" if pitch else ""
            failures.append(f"roll {roll:.2f}{above}: {why}")
            continue
        reached = world.joint_states(part)[joint]  # as the robot side reports it
        if abs(reached - goal) > PART_TOLERANCE:
            raise EnvironmentManipulationImpossible(
                f"{part}'s {joint} ended at {reached:.3f}, not {goal:.3f}, though the arm "
                "followed the handle: the robot side did not move the part with the hand",
                environment_part=joint,
                action=action,
            )
        return reached
    raise EnvironmentManipulationImpossible(
        f"{client.name}'s {arm} arm cannot hold {handle!r} while {joint!r} moves from "
        f"{start:.3f} to {goal:.3f} with any grasp roll, from the front or from above: "
        + "; ".join(failures),
        environment_part=joint,
        action=action,
    )


def _with_grasp(
    client: RosRobotClient,
    tools: ToolMover,
    arm: str,
    moving: tuple[str, str, str],
    grasp: Pose,
    goal: float,
    turn: Pose | None = None,
) -> str | None:
    """Move the part holding its handle with ``grasp`` (in the handle's frame ``turn``ed:
    from above); None if done, else why not (the hand then is open and off the handle)."""
    part, _, handle = moving
    world = _world(client, part, moving[1], goal)
    held = grasp if turn is None else turn * grasp
    torso = _torso_for_path(client, world, arm, moving, held, goal)
    if torso is None:
        return "no torso height lets the arm follow the handle"
    try:
        _raise_torso(client, torso)
        _take_handle(client, tools, arm, _frame(world, part, handle, turn), grasp)
    except REACHING as failure:
        return str(failure)
    path = _follow_path(client, world, arm, moving, held, goal)
    if path is not None:
        client.follow_trajectory(f"arm({arm})", path, _failure(arm, handle))
    _let_go(client, tools, arm, _frame(world, part, handle, turn), grasp)
    return None if path is not None else "the arm cannot keep the tool on the handle"


def _with_base_steps(
    client: RosRobotClient,
    tools: ToolMover,
    arm: str,
    moving: tuple[str, str, str],
    grasp: Pose,
    goal: float,
    turn: Pose | None = None,
) -> str | None:
    """Move the part holding its handle with ``grasp`` a step of the joint at a time, the
    base moving with the arm at each step (an arm that reaches with its base: Stretch's
    sideways arm cannot follow a drawer alone), as projection does; each step's base part
    goes to the navigation stack, then the arm's. None if done, else why not (the hand
    then is open and off the handle)."""
    part, joint, handle = moving
    world = _world(client, part, joint, goal)
    values = part_path(world, part, joint, handle, goal)
    try:
        _take_handle(client, tools, arm, _frame(world, part, handle, turn), grasp)
    except (*REACHING, *DRIVING) as failure:
        return str(failure)
    why = None
    try:
        for value in values:
            start = world.joint_states(part)[joint]
            world.set_joint_states(part, {joint: value})
            target = _frame(world, part, handle, turn) * grasp
            world.set_joint_states(part, {joint: start})
            tools.move_tcp(arm, target, "allow_hand", HANDLE, base_travel=STEP_TRAVEL)
    except (*REACHING, *DRIVING) as failure:
        why = f"the arm and base cannot keep the tool on the handle: {failure}"
    _let_go(client, tools, arm, _frame(world, part, handle, turn), grasp)
    return why


def _frame(world: World, part: str, handle: str, turn: Pose | None) -> Pose:
    """The frame (map) the hand holds ``handle`` in: the handle's own, or ``turn``ed."""
    pose = world.link_pose(part, handle)
    return pose if turn is None else pose * turn


def _world(client: RosRobotClient, part: str, joint: str, goal: float) -> World:
    """The world of the robot's environment, with ``goal`` inside the joint's limits."""
    if client.mirror is None:
        raise RosCommandError(
            f"moving-articulation of {part}'s {joint} over ROS needs a world of the "
            "environment (ros_robot(..., world=...)): the handle's pose and path are read there"
        )
    world = client.mirror.world
    limits = world.bodies.joint_limits(part, joint)
    if not limits.lower - 1e-9 <= goal <= limits.upper + 1e-9:
        raise RosCommandError(
            f"goal {goal:.3f} of {part}'s joint {joint!r} is outside its limits "
            f"[{limits.lower:.3f}, {limits.upper:.3f}]; ask for a value within them"
        )
    return world


def _take_handle(
    client: RosRobotClient, tools: ToolMover, arm: str, handle: Pose, grasp: Pose
) -> None:
    """Open the gripper, come from the front onto the handle, close the gripper."""
    move_gripper(client, arm, "open", None)
    tools.move_tcp(arm, handle * Pose((PRE_GRASP, 0.0, 0.0)) * grasp, "avoid_all")
    tools.move_tcp(arm, handle * grasp, "allow_hand", HANDLE)
    move_gripper(client, arm, "close", None)


def _let_go(client: RosRobotClient, tools: ToolMover, arm: str, handle: Pose, grasp: Pose) -> None:
    """Open the gripper and back the tool off the handle (as far as there is room).

    Fingers that cannot open at the handle (a drawer shut under a counter's top) open
    once the hand has backed off, if they can there, as in projection; the robot side
    let go of the handle when it was asked to open.
    """
    opened = _opened(client, arm)
    for distance in BACK_OFF:
        try:
            tools.move_tcp(arm, handle * Pose((distance, 0.0, 0.0)) * grasp, "allow_hand", HANDLE)
            break
        except (*REACHING, *DRIVING):
            continue
    if not opened:
        _opened(client, arm)


def _opened(client: RosRobotClient, arm: str) -> bool:
    """Open the gripper where the hand is; False if the controller could not."""
    try:
        move_gripper(client, arm, "open", None)
    except GripperGoalNotReached:
        return False
    return True


def _waypoints(
    client: RosRobotClient,
    world: World,
    arm: str,
    moving: tuple[str, str, str],
    grasp: Pose,
    values: list[float],
    seed: dict[str, float],
) -> list[list[float]] | None:
    """The arm's joints keeping the tool on the handle at each of the joint's ``values``,
    each solution near the last, the torso held at ``seed``'s (None if a step fails)."""
    part, joint, handle = moving
    desc, joints = client.desc, client.arm(arm).joints
    check = client.planner().ik_check(arm, joints, "allow_hand")  # syncs the world first
    to_base = client.base_pose().inverse()
    start = world.joint_states(part)[joint]
    waypoints: list[list[float]] = []
    last = [seed[j] for j in joints]
    try:
        for value in values:
            world.set_joint_states(part, {joint: value})
            target = to_base * world.link_pose(part, handle) * grasp
            result = solve_ik(
                desc, arm, target, seed=seed, options=_RANDOM_SEED, collision_check=check
            )
            if not result.success:
                return None
            point = [result.joint_positions[j] for j in joints]
            if waypoints and _jump(point, last) > MAX_JUMP:
                return None
            waypoints.append(point)
            last, seed = point, {**seed, **result.joint_positions}
    finally:
        world.set_joint_states(part, {joint: start})
    return waypoints


def _torso_for_path(
    client: RosRobotClient,
    world: World,
    arm: str,
    moving: tuple[str, str, str],
    grasp: Pose,
    goal: float,
) -> float | None:
    """A torso height [m] from which the arm holds the handle all the way (the current
    one if it does; else one IK picks at either end of the path); None if none does.

    The torso is its own controller and cannot move while the hand holds the handle, so
    it is chosen before the handle is taken (projection lets IK move it at each step).
    """
    part, joint, handle = moving
    current = client.actuated_joint_states()
    torso = client.desc.torso_joint
    start = world.joint_states(part)[joint]
    values = [start, *part_path(world, part, joint, handle, goal)]
    heights = [current[torso] if torso is not None else 0.0]
    if torso is not None:
        to_base = client.base_pose().inverse()
        for end in (goal, start):
            world.set_joint_states(part, {joint: end})
            target = to_base * world.link_pose(part, handle) * grasp
            world.set_joint_states(part, {joint: start})
            free = solve_ik(client.desc, arm, target, seed=current, options=_TORSO)
            if free.success:
                heights.append(free.joint_positions[torso])
    for height in heights:
        seed = {**current, torso: height} if torso is not None else current
        if _waypoints(client, world, arm, moving, grasp, values, seed) is not None:
            return height
    return None


def _raise_torso(client: RosRobotClient, height: float) -> None:
    """Move the torso to ``height`` [m] unless it is there."""
    torso = client.desc.torso_joint
    if torso is None or abs(client.joint_states()[torso] - height) < TORSO_MOVE:
        return
    client.move_joints(
        "torso", {torso: height}, lambda text: TorsoGoalNotReached(text, goal=height)
    )


def _follow_path(
    client: RosRobotClient,
    world: World,
    arm: str,
    moving: tuple[str, str, str],
    grasp: Pose,
    goal: float,
) -> JointTrajectory | None:
    """The arm's timed trajectory from where it holds the handle now, keeping the tool on
    it while the joint goes to ``goal`` (None if a step has no IK solution near the last)."""
    part, joint, handle = moving
    seed = client.actuated_joint_states()
    joints = client.arm(arm).joints
    start = world.joint_states(part)[joint]
    values = [start, *part_path(world, part, joint, handle, goal)]
    path = _waypoints(client, world, arm, moving, grasp, values, seed)
    here = [seed[j] for j in joints]
    if path is None or _jump(path[0], here) > MAX_JUMP:  # the first is where it holds now
        return None
    limits = joint_limits(client.desc, joints)
    return time_parameterize(client.desc.name, joints, [here, *path[1:]], limits, kind="arm")


def _jump(a: list[float], b: list[float]) -> float:
    """The largest change of one joint between two configurations [rad | m]."""
    return max(abs(x - y) for x, y in zip(a, b, strict=True))


def _failure(arm: str, handle: str) -> FailureFactory:
    return lambda text: ManipulationGoalNotReached(text, arm=arm, target=handle)

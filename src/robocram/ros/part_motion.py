"""Opening and closing articulated parts (drawers, doors) with an arm of a robot behind ROS.

As in projection (``projection/articulation.py``) the hand takes the handle from the front
and the tool stays on the handle while the part's joint moves. Over ROS that is a series
of goals: open the gripper, the tool before the handle and onto it (the arm's
``move_tcp``), close the gripper, then *one* arm trajectory through the IK solutions that
keep the tool on the handle at each step of the joint (planned in the world given to
``ros_robot``, arm only: the base stays where the plan put it), open the gripper and back
off. The robot side moves the part with the hand (a real drawer follows the hand pulling
it; our driver does so kinematically); the part's joint is then read back from its joint
states (``world_mirror.py``) and checked against the goal.

It needs that world: the handle's pose and how it moves with the joint are read there.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np

from robocram.execution.failures import (
    EnvironmentManipulationImpossible,
    ManipulationGoalNotReached,
    ManipulationPathBlocked,
    ManipulationPoseUnreachable,
)
from robocram.grasping import approach_axis
from robocram.kinematics import solve_ik
from robocram.motion import JointTrajectory, joint_limits, time_parameterize
from robocram.motion.part_path import BACK_OFF, PRE_GRASP, ROLLS, grasp_in_handle, part_path
from robocram.motion.tool_goal import IK_RANDOM_SEED
from robocram.ros.errors import RosCommandError
from robocram.ros.goal_runner import FailureFactory
from robocram.ros.gripper_goal import move_gripper
from robocram.ros.ros_robot_client import RosRobotClient
from robocram.tf import Pose
from robocram.world import World

PART_TOLERANCE = 0.01  # [m | rad] the part's joint ends this close to the goal
MAX_JUMP = 0.5  # [rad | m] an IK step moving a joint further is a flip, not a follow
REACHING = (ManipulationPoseUnreachable, ManipulationPathBlocked, ManipulationGoalNotReached)


class ToolMover(Protocol):
    """What moves a tool frame to a pose in map (the ROS arms' process module)."""

    def move_tcp(self, arm: str, target: Pose, collision_mode: str = "avoid_all") -> Pose: ...


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
    failures: list[str] = []
    for roll in ROLLS:
        grasp = grasp_in_handle(axis, roll)
        try:
            _take_handle(client, tools, arm, world.link_pose(part, handle), grasp)
        except REACHING as failure:
            failures.append(f"roll {roll:.2f}: {failure}")
            continue
        path = _follow_path(client, world, arm, (part, joint, handle), grasp, goal)
        if path is not None:
            client.follow_trajectory(f"arm({arm})", path, _failure(arm, handle))
        _let_go(client, tools, arm, world.link_pose(part, handle), grasp)
        if path is None:
            failures.append(f"roll {roll:.2f}: the arm cannot keep the tool on the handle")
            continue
        reached = world.joint_states(part)[joint]
        if abs(reached - goal) > PART_TOLERANCE:
            raise EnvironmentManipulationImpossible(
                f"{part}'s {joint} ended at {reached:.3f}, not {goal:.3f}, though the arm "
                "followed the handle: the robot side did not move the part with the hand",
                environment_part=joint,
                action="opening" if goal > start else "closing",
            )
        return reached
    raise EnvironmentManipulationImpossible(
        f"{client.name}'s {arm} arm cannot hold {handle!r} while {joint!r} moves from "
        f"{start:.3f} to {goal:.3f} with any grasp roll: " + "; ".join(failures),
        environment_part=joint,
        action="opening" if goal > start else "closing",
    )


def _world(client: RosRobotClient, part: str, joint: str, goal: float) -> World:
    """The world of the robot's environment, with ``goal`` inside the joint's limits."""
    if client.mirror is None:
        raise RosCommandError(
            f"moving-articulation of {part}'s {joint} over ROS needs a world of the "
            "environment (ros_robot(..., world=...)): the handle's pose and path are read there"
        )
    world = client.mirror.world
    limits = world.joint_limits(part, joint)
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
    tools.move_tcp(arm, handle * grasp, "allow_hand")
    move_gripper(client, arm, "close", None)


def _let_go(client: RosRobotClient, tools: ToolMover, arm: str, handle: Pose, grasp: Pose) -> None:
    """Open the gripper and back the tool off the handle (as far as there is room)."""
    move_gripper(client, arm, "open", None)
    for distance in BACK_OFF:
        try:
            tools.move_tcp(arm, handle * Pose((distance, 0.0, 0.0)) * grasp, "allow_hand")
            return
        except REACHING:
            continue


def _follow_path(
    client: RosRobotClient,
    world: World,
    arm: str,
    moving: tuple[str, str, str],
    grasp: Pose,
    goal: float,
) -> JointTrajectory | None:
    """The arm's timed trajectory keeping the tool on the handle while the joint goes to
    ``goal`` (None if a step has no IK solution near the last), planned in ``world``."""
    part, joint, handle = moving
    desc, joints = client.desc, client.arm(arm).joints
    planner = client.planner()  # the world in the robot's state now
    check = planner.ik_check(arm, joints, "allow_hand")
    seed = client.actuated_joint_states()
    to_base = client.base_pose().inverse()
    start = world.joint_states(part)[joint]
    waypoints = [[seed[j] for j in joints]]
    try:
        for value in part_path(world, part, joint, handle, goal):
            world.set_joint_states(part, {joint: value})
            target = to_base * world.link_pose(part, handle) * grasp
            result = solve_ik(
                desc, arm, target, seed=seed, collision_check=check, random_seed=IK_RANDOM_SEED
            )
            if not result.success:
                return None
            point = [result.joint_positions[j] for j in joints]
            if max(abs(a - b) for a, b in zip(point, waypoints[-1], strict=True)) > MAX_JUMP:
                return None
            waypoints.append(point)
            seed = {**seed, **result.joint_positions}
    finally:
        world.set_joint_states(part, {joint: start})
    limits = joint_limits(desc, joints)
    return time_parameterize(desc.name, joints, waypoints, limits, kind="arm")


def _failure(arm: str, handle: str) -> FailureFactory:
    return lambda text: ManipulationGoalNotReached(text, arm=arm, target=handle)

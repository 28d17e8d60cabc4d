"""One gripper goal of a robot behind ROS: the description's opening turned into the
controller's command, and the controller's answer turned back (``gripper_semantics.py``).

Positions are the description's gripper joint values; the robot's gripper semantics say
the command's unit and what a holding gripper reports (the PR2: ABORTED with
``stalled``). With a world, the object a holding hand closed on is attached to it there,
and opening lets it go. The gripper process module and the articulation (taking and
letting go of a handle) both send their goals through here.
"""

from __future__ import annotations

from dataclasses import replace

from robocram.execution.failures import GripperClosedCompletely, GripperGoalNotReached
from robocram.ros.errors import RosCommandError
from robocram.ros.ros_robot_client import RosRobotClient
from robocram.ros.transport import GoalOutcome, RosDict

PARALLEL = "control_msgs/ParallelGripperCommand"  # ros2_controllers' parallel gripper


def _goal(parallel: bool, joint: str, command: float, force: float) -> RosDict:
    """A GripperCommand goal, or a ParallelGripperCommand's (its command a JointState)."""
    if parallel:
        return {"command": {"name": [joint], "position": [command], "effort": [force]}}
    return {"command": {"position": command, "max_effort": force}}


def _flat(outcome: GoalOutcome) -> GoalOutcome:
    """A ParallelGripperCommand result's ``state`` (a JointState) as GripperCommand's
    ``position`` and ``effort``, so both read alike; others unchanged."""
    state = outcome.result.get("state")
    if not isinstance(state, dict) or not state.get("position"):
        return outcome
    efforts = state.get("effort") or [0.0]
    flat = {**outcome.result, "position": state["position"][0], "effort": efforts[0]}
    return replace(outcome, result=flat)


def move_gripper(client: RosRobotClient, gripper: str, action: object, effort: object) -> float:
    """Open, close or grip with ``gripper``'s hand, or move it to a position [rad | m];
    return the description's gripper joint value reached.

    Raises:
        GripperClosedCompletely: ``grip`` closed on nothing (not holding by the facts).
        GripperGoalNotReached: the controller failed.
    """
    arm = client.desc.arm_called(str(gripper))
    semantics = client.config.grippers.get(arm)
    if semantics is None:
        raise RosCommandError(f"{client.name}'s {arm} arm has no bounded gripper joint")
    lower, upper = semantics.joint_range
    positions = {"open": upper, "close": lower, "grip": lower}
    if action in positions:
        position = positions[action]
    elif isinstance(action, int | float):
        position = float(action)
    else:
        raise RosCommandError(f"gripper goal {action!r} is none of open, close, grip or a position")
    force = float(effort) if isinstance(effort, int | float) else semantics.effort
    command = semantics.command(position)
    resource = f"gripper({arm})"
    parallel = client.config.action(resource).action_type == PARALLEL
    joint = client.arm(arm).gripper_joints[0] if parallel else ""
    goal = _goal(parallel, joint, command, force)
    closing = action in ("close", "grip")
    outcome = _flat(
        client.run(
            resource,
            goal,
            lambda text: GripperGoalNotReached(text, gripper=arm, goal=position),
            accept=(lambda end: semantics.holds(_flat(end))) if closing else None,
        )
    )
    reached = semantics.joint_value(float(outcome.result.get("position", command)))
    holding = closing and semantics.holds(outcome)
    if client.mirror is not None:  # what the hand holds moves with it there
        if holding:
            client.mirror.hold(arm)
        elif not closing:
            client.mirror.release(arm)
    if action == "grip" and not holding:
        raise GripperClosedCompletely(
            f"{client.name}'s {arm} gripper closed on nothing ({outcome.state.name}, "
            f"stalled={bool(outcome.result.get('stalled', False))}, position "
            f"{outcome.result.get('position')} {semantics.unit})",
            gripper=arm,
            position=reached,
        )
    return reached

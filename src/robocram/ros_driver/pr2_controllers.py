"""The real PR2's controller semantics, for the driver's ``--controllers pr2`` mode.

Written from the PR2's public controller behaviour, independently of the plan side:

- ``pr2_gripper_action`` reads ``GripperCommand.position`` as the gap between the fingers
  [m]. pr2_description's ``<side>_gripper_joint`` spans 0 .. 0.09 m (the finger joint
  ``<side>_gripper_l_finger_joint`` 0 .. 0.548 rad) and its ``safety_controller`` stops
  the gap at 0.088 m. A goal the fingers stop short of (an object, the soft limit) by more
  than the action's ``goal_threshold`` (0.01 m) stalls: the goal ends ABORTED with
  ``stalled = true`` and the gap reached, no status text. A goal reached SUCCEEDED.
- The arms' and torso's ``safety_controller`` soft limits (``soft_lower_limit``,
  ``soft_upper_limit`` in the URDF) clamp every joint silently; the trajectory action then
  aborts at the goal check with only ``error_code`` and ``error_string``.
"""

from __future__ import annotations

from pathlib import Path
from xml.etree import ElementTree

from robocram.execution.failures import GripperClosedCompletely
from robocram.projection.gripper import grip, gripper_joints, release, set_gripper
from robocram.ros_driver.goals import GoalContext, Outcome, RosMessage

GAP_AT_UPPER = 0.09  # [m] the gap of pr2_description's gripper_joint at its upper limit
GAP_SOFT_UPPER = 0.088  # [m] its safety_controller soft_upper_limit
GOAL_THRESHOLD = 0.01  # [m] pr2_gripper_action's default goal_threshold
CLOSED = 1e-4  # [m] a command gap this small closes the gripper


def soft_limits(urdf: str | Path) -> dict[str, tuple[float, float]]:
    """``joint: (soft_lower, soft_upper)`` of every joint with a ``<safety_controller>``."""
    limits: dict[str, tuple[float, float]] = {}
    for joint in ElementTree.parse(urdf).getroot().iter("joint"):
        safety = joint.find("safety_controller")
        if safety is not None and "soft_lower_limit" in safety.attrib:
            limits[joint.attrib["name"]] = (
                float(safety.attrib["soft_lower_limit"]),
                float(safety.attrib["soft_upper_limit"]),
            )
    return limits


def gripper_command(goal: RosMessage, ctx: GoalContext, arm: str) -> Outcome:
    """``GripperCommand`` as ``pr2_gripper_action``: a gap [m], stalls end ABORTED."""
    robot, wanted = ctx.robot, float(goal.command.position)
    with ctx.stepper.lock:
        joint = gripper_joints(robot, arm)[0]
        upper = robot.world.bodies.joint_limits(robot.name, joint).upper
        per_metre = upper / GAP_AT_UPPER  # [rad/m]
        if wanted <= CLOSED:
            try:
                grip(robot, arm)
            except GripperClosedCompletely:  # closed fully: reached 0, or a handle's bar
                ctx.handles.grasp(robot, arm)
        else:
            ctx.handles.release(robot, arm)
            release(robot, arm)
            set_gripper(robot, arm, min(max(wanted, 0.0), GAP_SOFT_UPPER) * per_metre)
        gap = robot.world.joint_states(robot.name)[joint] / per_metre
    reached = abs(gap - wanted) < GOAL_THRESHOLD
    effort = 0.0 if reached else float(goal.command.max_effort)
    result = {"position": gap, "effort": effort, "stalled": not reached, "reached_goal": reached}
    return reached, result, ""

"""What a gripper controller's command means, and what it reports when it holds something.

The description knows the gripper joint (``ArmDescription.gripper_joints[0]``) and its
limits; the controller may want something else. The PR2's ``pr2_gripper_action`` reads
``GripperCommand.position`` as the gap between the fingers in metres and ends a goal on
an object ABORTED with ``stalled``; other controllers take the joint value and succeed.
Per gripper, from the robot's ROS facts (defaults from the description):

```prolog
% the command at the gripper joint's lower (closed) and upper (open) limit, and its unit
ros_gripper_command(Robot, Arm, Unit, Closed, Open).     % Unit: gap [m] | joint [rad | m]
% a held object ends the goal in Status (aborted | succeeded) with stalled = true and the
% command-unit position above MinPosition (aborted: a SUCCEEDED goal above it holds too,
% a thin object the fingers stopped on within the controller's goal threshold)
ros_gripper_holding(Robot, Arm, Status, MinPosition).
ros_gripper_effort(Robot, Newtons).                      % max_effort of every command
```

A description position ``q`` maps linearly: ``Closed + (Open - Closed) * (q - lower) /
(upper - lower)``, and a reported position maps back the same way.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from robocram.logic import KnowledgeBase, UnknownPredicateError
from robocram.robots import RobotDescription
from robocram.ros.errors import RosConfigError
from robocram.ros.transport import GoalOutcome, GoalState

UNITS = ("gap", "joint")
HOLDING_STATUS = {"aborted": GoalState.ABORTED, "succeeded": GoalState.SUCCEEDED}


@dataclass(frozen=True)
class GripperSemantics:
    """One gripper's command unit and range, effort and what counts as holding."""

    arm: str
    joint: str  # the description's gripper joint
    joint_range: tuple[float, float]  # [rad | m] its (lower, upper) limits
    unit: str  # "gap" [m] or "joint" [rad | m]
    command_range: tuple[float, float]  # [unit] the commands at (lower, upper)
    effort: float  # [N]
    holding_status: GoalState = GoalState.SUCCEEDED
    holding_min: float = 0.0  # [unit] a held object keeps the gripper at least this open

    def command(self, joint_value: float) -> float:
        """The command [unit] for the description's gripper joint at ``joint_value``."""
        (q0, q1), (c0, c1) = self.joint_range, self.command_range
        return c0 + (c1 - c0) * (joint_value - q0) / (q1 - q0)

    def joint_value(self, command: float) -> float:
        """The description's gripper joint value for a reported position [unit]."""
        (q0, q1), (c0, c1) = self.joint_range, self.command_range
        return q0 + (q1 - q0) * (command - c0) / (c1 - c0)

    def holds(self, outcome: GoalOutcome) -> bool:
        """Whether a closing goal's outcome says an object is held between the fingers.

        A controller that aborts on holding (the PR2's) succeeds when the fingers stop
        within its goal threshold of the command: closing on a thin object (a bowl's
        rim) ends SUCCEEDED with a gap, so there the gap alone decides, as CRAM's PR2
        gripping does.
        """
        result = outcome.result
        gap = float(result.get("position", self.holding_min)) > self.holding_min
        if outcome.state is self.holding_status and bool(result.get("stalled", False)):
            return gap
        thin = self.holding_status is GoalState.ABORTED and outcome.state is GoalState.SUCCEEDED
        return thin and gap


def _first(kb: KnowledgeBase, goal: str, **bindings: object) -> dict[str, Any] | None:
    try:
        return kb.first(goal, **bindings)
    except UnknownPredicateError:
        return None


def _number(robot_name: str, fact: str, value: object) -> float:
    if not isinstance(value, int | float):
        raise RosConfigError(f"{fact} gives {value!r}; it must be a number")
    return float(value)


def read_gripper_semantics(
    kb: KnowledgeBase, desc: RobotDescription, arm: str, effort: float
) -> GripperSemantics | None:
    """The semantics of ``arm``'s gripper (None: the arm has no bounded gripper joint).

    Raises:
        RosConfigError: a fact has an unknown unit or status, equal ends, or no numbers.
    """
    robot, spec, model = desc.name, desc.arms[arm], desc.model
    joint = model.joints.get(spec.gripper_joints[0]) if model and spec.gripper_joints else None
    if joint is None or joint.lower is None or joint.upper is None or joint.lower >= joint.upper:
        return None
    limits = (joint.lower, joint.upper)
    fact = f"ros_gripper_command({robot}, {arm}, Unit, Closed, Open)"
    answer = _first(kb, "ros_gripper_command(R, A, U, C, O)", R=robot, A=arm)
    unit, commands = "joint", limits
    if answer is not None:
        unit = str(answer["U"])
        commands = (_number(robot, fact, answer["C"]), _number(robot, fact, answer["O"]))
        if unit not in UNITS or commands[0] == commands[1]:
            raise RosConfigError(
                f"{fact} gives unit {unit!r} and commands {commands}; use a unit of {UNITS} "
                "and two different commands"
            )
    status, minimum = GoalState.SUCCEEDED, commands[0]
    holding = _first(kb, "ros_gripper_holding(R, A, S, M)", R=robot, A=arm)
    if holding is not None:
        name = str(holding["S"])
        if name not in HOLDING_STATUS:
            raise RosConfigError(
                f"ros_gripper_holding({robot}, {arm}, {name}, _): the status is none of "
                f"{sorted(HOLDING_STATUS)}"
            )
        status = HOLDING_STATUS[name]
        minimum = _number(robot, f"ros_gripper_holding({robot}, {arm}, S, Min)", holding["M"])
    return GripperSemantics(arm, joint.name, limits, unit, commands, effort, status, minimum)

"""A robot's ROS interfaces, read from knowledge-base facts so new robots need no code.

``robots/<robot>.pl`` holds the defaults (PR2 as in CRAM, HSR); pass other fact text to
use other controllers. :func:`read_ros_config` asks the knowledge base and checks that
every resource the robot's description has is served, naming the missing fact.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from importlib import resources
from typing import Any

from robocram.logic import KnowledgeBase, Term, UnknownPredicateError
from robocram.robots import RobotDescription
from robocram.ros.errors import RosConfigError
from robocram.ros.goal_tolerances import GoalTolerances, read_goal_tolerances
from robocram.ros.gripper_semantics import GripperSemantics, read_gripper_semantics

ROS_FACTS_GROUP = "ros_interfaces"
ACTION_TYPES = (
    "move_base_msgs/MoveBase",
    "nav2_msgs/NavigateToPose",
    "control_msgs/FollowJointTrajectory",
    "control_msgs/PointHead",
    "control_msgs/GripperCommand",
    "control_msgs/ParallelGripperCommand",
    "robocram_msgs/DetectObjects",
    "pr2_controllers_msgs/JointTrajectory",
    "pr2_controllers_msgs/SingleJointPosition",
    "pr2_controllers_msgs/PointHead",
    "pr2_controllers_msgs/Pr2GripperCommand",
)
DEFAULT_CANCEL_TIMEOUT = 2.0  # [s] for a server to confirm a cancel (ros_cancel_timeout/2)
DEFAULT_SKEW_BOUND = 0.5  # [s] a larger robot clock offset is reported (ros_clock_skew_bound/2)


@dataclass(frozen=True)
class ActionInterface:
    """One resource's action server, its action type and its time budget."""

    resource: str  # "navigation", "torso", "head", "perception", "arm(left)", "gripper(left)"
    server: str
    action_type: str
    timeout: float  # [s]
    cancel_timeout: float = DEFAULT_CANCEL_TIMEOUT  # [s] for the server to confirm a cancel


@dataclass(frozen=True)
class RosConfig:
    """Everything robocram.ros needs to know about a robot's ROS side."""

    robot: str
    actions: dict[str, ActionInterface]
    joint_states_topic: str
    connection_timeout: float  # [s] of status silence that count as a lost connection
    server_timeout: float  # [s] to wait for an action server to appear
    gripper_effort: float  # [N]
    goal_tolerances: GoalTolerances = field(default_factory=GoalTolerances)
    grippers: dict[str, GripperSemantics] = field(default_factory=dict)  # by arm
    clock_skew_bound: float = DEFAULT_SKEW_BOUND  # [s] a larger robot clock offset is reported
    environment_topics: dict[str, str] = field(default_factory=dict)  # env -> joint states

    def action(self, resource: str) -> ActionInterface:
        """The interface of ``resource``, or a RosConfigError naming the missing fact."""
        if resource not in self.actions:
            raise RosConfigError(
                f"{self.robot} has no ros_action({self.robot}, {resource}, Server, Type) fact; "
                f"add one (it serves {sorted(self.actions)})"
            )
        return self.actions[resource]

    def servers(self) -> dict[str, str]:
        """Every action server and its action type."""
        return {a.server: a.action_type for a in self.actions.values()}


def default_facts(robot_name: str, ros: int = 1) -> str:
    """The packaged ROS facts of a built-in robot (``robots/<robot>.pl``; for ROS 2
    ``robots/<robot>_ros2.pl``: ros2_control's and Nav2's names)."""
    name = f"{robot_name}.pl" if ros == 1 else f"{robot_name}_ros2.pl"
    path = resources.files("robocram.ros").joinpath("robots", name)
    if not path.is_file():
        have = "pr2, hsrb" if ros == 1 else "pr2"
        raise RosConfigError(
            f"robocram.ros ships no ROS facts for {robot_name!r} (ROS {ros}: have {have}); pass "
            "ros_facts= with ros_action/4, ros_topic/3, ros_action_timeout/3 facts for it"
        )
    return path.read_text()


def resource_key(term: Any) -> str:
    """``arm(left)`` -> ``"arm(left)"``; an atom stays as it is."""
    if isinstance(term, Term):
        return f"{term.name}({', '.join(str(a) for a in term.args)})"
    return str(term)


def _first(kb: KnowledgeBase, goal: str, **bindings: object) -> dict[str, Any] | None:
    """The first answer, or None also when no clause of the predicate exists at all."""
    try:
        return kb.first(goal, **bindings)
    except UnknownPredicateError:
        return None


def _number(kb: KnowledgeBase, predicate: str, robot_name: str, unit: str) -> float:
    answer = _first(kb, f"{predicate}(R, S)", R=robot_name)
    if answer is None:
        raise RosConfigError(
            f"{robot_name} lacks the fact {predicate}({robot_name}, Value) [{unit}]"
        )
    return float(answer["S"])


def _optional(kb: KnowledgeBase, predicate: str, robot_name: str, default: float) -> float:
    answer = _first(kb, f"{predicate}(R, S)", R=robot_name)
    if answer is None:
        return default
    value = answer["S"]
    if not isinstance(value, int | float) or value <= 0:
        raise RosConfigError(f"{predicate}({robot_name}, {value!r}): give a number of seconds > 0")
    return float(value)


def _interface(kb: KnowledgeBase, robot_name: str, answer: dict[str, Any]) -> ActionInterface:
    resource, server, kind = answer["Res"], str(answer["Server"]), str(answer["Type"])
    if kind not in ACTION_TYPES:
        raise RosConfigError(
            f"ros_action({robot_name}, {resource_key(resource)}, {server}, {kind}): unknown action "
            f"type; use one of {list(ACTION_TYPES)}"
        )
    timeout = _first(kb, "ros_action_timeout(R, Res, S)", R=robot_name, Res=resource)
    if timeout is None:
        raise RosConfigError(
            f"{robot_name} lacks ros_action_timeout({robot_name}, {resource_key(resource)}, "
            "Seconds)"
        )
    cancel = _optional(kb, "ros_cancel_timeout", robot_name, DEFAULT_CANCEL_TIMEOUT)
    return ActionInterface(resource_key(resource), server, kind, float(timeout["S"]), cancel)


def read_ros_config(kb: KnowledgeBase, desc: RobotDescription) -> RosConfig:
    """The ROS interfaces of ``desc``'s robot from the facts in ``kb``."""
    robot = desc.name
    actions: dict[str, ActionInterface] = {}
    try:
        answers = list(kb.query("ros_action(R, Res, Server, Type)", R=robot))
    except UnknownPredicateError:
        answers = []
    for answer in answers:
        interface = _interface(kb, robot, answer)
        actions.setdefault(interface.resource, interface)  # the first answer wins, as for
        # every ROS fact: facts put before the defaults override them
    topic = _first(kb, "ros_topic(R, joint_states, T)", R=robot)
    if topic is None:
        raise RosConfigError(f"{robot} lacks the fact ros_topic({robot}, joint_states, Topic)")
    try:
        environments = {
            resource_key(a["Env"]): str(a["T"])
            for a in kb.query("ros_topic(R, joint_states(Env), T)", R=robot)
        }
    except UnknownPredicateError:
        environments = {}
    effort = _number(kb, "ros_gripper_effort", robot, "N")
    grippers = {
        arm: semantics
        for arm in desc.arms
        if (semantics := read_gripper_semantics(kb, desc, arm, effort)) is not None
    }
    return RosConfig(
        robot=robot,
        actions=actions,
        joint_states_topic=str(topic["T"]),
        connection_timeout=_number(kb, "ros_connection_timeout", robot, "s"),
        server_timeout=_number(kb, "ros_server_timeout", robot, "s"),
        gripper_effort=effort,
        goal_tolerances=read_goal_tolerances(kb, desc),
        grippers=grippers,
        clock_skew_bound=_optional(kb, "ros_clock_skew_bound", robot, DEFAULT_SKEW_BOUND),
        environment_topics=environments,
    )


def install_ros_facts(
    kb: KnowledgeBase, robot_name: str, facts: str | None = None, ros: int = 1
) -> None:
    """Load ``facts`` (default: the robot's packaged facts for ROS ``ros``) into ``kb``."""
    text = facts if facts is not None else default_facts(robot_name, ros)
    kb.consult(text, group=ROS_FACTS_GROUP)

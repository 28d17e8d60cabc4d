"""How close a ``FollowJointTrajectory`` goal must end: per joint, and in time.

Every trajectory goal carries ``goal_tolerance`` (how far each joint may stop from the
last point) and ``goal_time_tolerance`` (how long after the last point's time the joints
may take to get there), as control_msgs defines them. They come from the robot's ROS
facts; a joint without a fact gets the default of its kind from the description:

```prolog
ros_goal_tolerance(Robot, Joint, Tolerance).   % [rad | m] a joint's position tolerance
ros_goal_time_tolerance(Robot, Seconds).       % [s] after the last point's time
```
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from robocram.logic import KnowledgeBase, UnknownPredicateError
from robocram.robots import RobotDescription
from robocram.ros.errors import RosConfigError

# [rad | m] position tolerance by joint type when the facts name none: a joint ends well
# inside the 1 cm / 0.05 rad a reached tool frame is checked to
DEFAULT_POSITION_TOLERANCE = {"revolute": 0.02, "continuous": 0.02, "prismatic": 0.005}
FALLBACK_POSITION_TOLERANCE = 0.01  # [rad | m] joints of other or unknown types
DEFAULT_GOAL_TIME_TOLERANCE = 0.5  # [s]


@dataclass(frozen=True)
class GoalTolerances:
    """Position tolerances by joint [rad | m] and the goal time tolerance [s]."""

    positions: dict[str, float] = field(default_factory=dict)
    time: float = DEFAULT_GOAL_TIME_TOLERANCE

    def position(self, joint: str) -> float:
        """The position tolerance of ``joint`` [rad | m]."""
        return self.positions.get(joint, FALLBACK_POSITION_TOLERANCE)

    def to_ros(self, joints: Sequence[str]) -> dict[str, object]:
        """The ``goal_tolerance`` and ``goal_time_tolerance`` fields of a goal for ``joints``.

        Velocity and acceleration tolerances are 0, the controller's defaults.
        """
        secs = int(self.time)
        return {
            "goal_tolerance": [
                {"name": j, "position": self.position(j), "velocity": 0.0, "acceleration": 0.0}
                for j in joints
            ],
            "goal_time_tolerance": {"secs": secs, "nsecs": int(round((self.time - secs) * 1e9))},
        }


def _answers(kb: KnowledgeBase, goal: str, robot_name: str) -> list[dict[str, object]]:
    try:
        return list(kb.query(goal, R=robot_name))
    except UnknownPredicateError:
        return []


def _positive(robot_name: str, fact: str, value: object) -> float:
    try:
        number = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        number = -1.0
    if not number > 0.0:
        raise RosConfigError(f"{fact} gives {value!r}; a tolerance of {robot_name} must be > 0")
    return number


def read_goal_tolerances(kb: KnowledgeBase, desc: RobotDescription) -> GoalTolerances:
    """The tolerances of ``desc``'s movable joints: facts first, else the joint type's default.

    Raises:
        RosConfigError: a fact names a joint the robot does not have, or a value <= 0.
    """
    robot = desc.name
    model = desc.model
    joints = {j.name: str(j.type) for j in model.movable_joints()} if model is not None else {}
    positions = {
        name: DEFAULT_POSITION_TOLERANCE.get(kind, FALLBACK_POSITION_TOLERANCE)
        for name, kind in joints.items()
    }
    first: set[str] = set()
    for answer in _answers(kb, "ros_goal_tolerance(R, J, T)", robot):
        joint = str(answer["J"])
        if joints and joint not in joints:
            raise RosConfigError(
                f"ros_goal_tolerance({robot}, {joint}, _) names no movable joint of {robot}; "
                f"use one of {sorted(joints)}"
            )
        if joint not in first:  # the first answer wins, as for every ROS fact
            first.add(joint)
            fact = f"ros_goal_tolerance({robot}, {joint}, T)"
            positions[joint] = _positive(robot, fact, answer["T"])
    time = DEFAULT_GOAL_TIME_TOLERANCE
    answers = _answers(kb, "ros_goal_time_tolerance(R, S)", robot)
    if answers:
        time = _positive(robot, f"ros_goal_time_tolerance({robot}, S)", answers[0]["S"])
    return GoalTolerances(positions, time)

"""A timed joint trajectory as the goal of the action type that serves it.

``control_msgs/FollowJointTrajectory`` takes the whole trajectory with the goal
tolerances; the PR2's native ``pr2_controllers_msgs/JointTrajectory`` the trajectory
alone (its controller has its own constraints); ``pr2_controllers_msgs/SingleJointPosition``
(the PR2's torso) one joint's last position, reached no sooner than the trajectory's
duration.
"""

from __future__ import annotations

from robocram.motion import JointTrajectory
from robocram.ros.errors import RosConfigError
from robocram.ros.goal_tolerances import GoalTolerances
from robocram.ros.transport import RosDict

TRAJECTORY_TYPES = (
    "control_msgs/FollowJointTrajectory",
    "pr2_controllers_msgs/JointTrajectory",
    "pr2_controllers_msgs/SingleJointPosition",
)


def _duration(seconds: float) -> RosDict:
    secs = int(seconds)
    return {"secs": secs, "nsecs": int(round((seconds - secs) * 1e9))}


def trajectory_goal(
    action_type: str, trajectory: JointTrajectory, tolerances: GoalTolerances
) -> RosDict:
    """The goal message (as a dict) moving along ``trajectory`` on a server of ``action_type``.

    Raises:
        RosConfigError: the type moves no joints, or ``SingleJointPosition`` gets more
            than one joint.
    """
    if action_type == "control_msgs/FollowJointTrajectory":
        return {"trajectory": trajectory.to_ros(), **tolerances.to_ros(trajectory.joint_names)}
    if action_type == "pr2_controllers_msgs/JointTrajectory":
        return {"trajectory": trajectory.to_ros()}
    if action_type == "pr2_controllers_msgs/SingleJointPosition":
        if len(trajectory.joint_names) != 1:
            raise RosConfigError(
                f"a SingleJointPosition server moves one joint, not {list(trajectory.joint_names)}"
                "; serve these joints with a (Follow)JointTrajectory server in ros_action/4"
            )
        return {
            "position": trajectory.points[-1].positions[0],
            "min_duration": _duration(trajectory.duration),
            "max_velocity": 0.0,  # the controller's own limit
        }
    raise RosConfigError(
        f"{action_type} servers cannot follow joint trajectories; use one of {TRAJECTORY_TYPES}"
    )

"""robocram.ros: run the same plans on real robots through ROS 1 or ROS 2 (an optional extra).

``with ros_robot("pr2", master_uri=...):`` is CRAM's ``on-real-pr2``: PERFORM goes to
process modules that send ``move_base``, ``FollowJointTrajectory``, ``PointHead``,
``GripperCommand`` and our ``DetectObjects`` goals, with controller names from the
robot's ROS facts. Our ROS node runs in a child process behind the :class:`Transport`
interface. ``python -m robocram.ros_driver`` serves the same interfaces from a projection
world. ``ros_robot(..., ros=2)`` speaks ROS 2 (ros2_control, Nav2; docs/ros2.md).
Importing this package with neither ROS set up raises :class:`RosExtraMissing`.
"""

from typing import TYPE_CHECKING, Any

from robocram.ros.availability import require_some_ros

require_some_ros()

from robocram.ros.errors import (  # noqa: E402 - only once the extra is known to be there
    RosCancelIgnored,
    RosConfigError,
    RosConnectionLost,
    RosError,
    RosExtraMissing,
    RosJointStateInvalid,
    RosMasterUnreachable,
    RosNodeError,
)

if TYPE_CHECKING:
    from robocram.ros.ros_block import RosEnvironment, RosRun, ros_environment, ros_robot
    from robocram.ros.ros_config import RosConfig, install_ros_facts, read_ros_config
    from robocram.ros.roscore import Roscore
    from robocram.ros.transport import GoalOutcome, GoalState, Transport

# Imported on first use: our node's child process imports robocram.ros.ros1_node, and
# with it this package, and must not pay for the plan side (projection, PyBullet).
_LAZY = {
    "RosConfig": "ros_config",
    "install_ros_facts": "ros_config",
    "read_ros_config": "ros_config",
    "RosEnvironment": "ros_block",
    "RosRun": "ros_block",
    "ros_environment": "ros_block",
    "ros_robot": "ros_block",
    "Roscore": "roscore",
    "GoalOutcome": "transport",
    "GoalState": "transport",
    "Transport": "transport",
}


def __getattr__(name: str) -> Any:
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'robocram.ros' has no attribute {name!r}")
    import importlib

    loaded = importlib.import_module(f"robocram.ros.{module}")
    for lazy, home in _LAZY.items():  # also over the submodule of the same name (ros_robot)
        if home == module:
            globals()[lazy] = getattr(loaded, lazy)
    return globals()[name]


__all__ = [
    "GoalOutcome",
    "GoalState",
    "RosCancelIgnored",
    "RosConfig",
    "RosConfigError",
    "RosConnectionLost",
    "RosJointStateInvalid",
    "RosEnvironment",
    "RosError",
    "RosExtraMissing",
    "RosMasterUnreachable",
    "RosNodeError",
    "RosRun",
    "Roscore",
    "Transport",
    "install_ros_facts",
    "read_ros_config",
    "ros_environment",
    "ros_robot",
]

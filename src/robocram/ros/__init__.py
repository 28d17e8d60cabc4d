"""robocram.ros: run the same plans on real robots through ROS 1 (an optional extra).

``with ros_robot("pr2", master_uri=...):`` is CRAM's ``on-real-pr2``: PERFORM goes to
process modules that send ``move_base``, ``FollowJointTrajectory``, ``PointHead``,
``GripperCommand`` and our ``DetectObjects`` goals, with controller names from the
robot's ROS facts. Our ROS node runs in a child process behind the :class:`Transport`
interface. ``python -m robocram.ros.driver`` serves the same interfaces from a projection
world. Importing this package without the extra raises :class:`RosExtraMissing`.
"""

from robocram.ros.availability import require_ros_extra

require_ros_extra()

from robocram.ros.errors import (  # noqa: E402 - only once the extra is known to be there
    RosCancelIgnored,
    RosConfigError,
    RosConnectionLost,
    RosError,
    RosExtraMissing,
    RosMasterUnreachable,
    RosNodeError,
)
from robocram.ros.ros_config import RosConfig, install_ros_facts, read_ros_config  # noqa: E402
from robocram.ros.ros_robot import RosEnvironment, RosRun, ros_environment, ros_robot  # noqa: E402
from robocram.ros.roscore import Roscore  # noqa: E402
from robocram.ros.transport import GoalOutcome, GoalState, Transport  # noqa: E402

__all__ = [
    "GoalOutcome",
    "GoalState",
    "RosCancelIgnored",
    "RosConfig",
    "RosConfigError",
    "RosConnectionLost",
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

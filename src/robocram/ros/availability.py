"""Is the ROS extra installed? Checked when robocram.ros is imported, so the error says how.

ROS 1 and ROS 2 are set up apart (``ros2_environment.py``): the package imports if either
is, and ``ros_robot`` checks the one it is asked for.

The plan-side code never imports rospy itself (our ROS node runs in a child process), but
without the Debian packages and the generated messages nothing here can work, so the
package refuses to import with :class:`RosExtraMissing` naming the missing module.
"""

from __future__ import annotations

import importlib.util

from robocram.ros.errors import INSTALL_HINT, RosExtraMissing

REQUIRED = (
    "rospy",
    "actionlib",
    "tf2_ros",
    "move_base_msgs",
    "sensor_msgs",
    "control_msgs",
    "robocram_msgs",
)


def missing_modules() -> list[str]:
    """The modules of the ROS extra that cannot be found."""
    return [name for name in REQUIRED if importlib.util.find_spec(name) is None]


def require_some_ros() -> None:
    """Raise :class:`RosExtraMissing` unless ROS 1 or ROS 2 is set up: this package
    serves both (``ros_robot(..., ros=2)``), and our ROS 2 processes run without ROS 1."""
    missing = missing_modules()
    if not missing or importlib.util.find_spec("rclpy") is not None:
        return
    from robocram.ros.ros2_environment import SETUP_HINT, ros2_prefix

    if not ros2_prefix().missing():
        return
    raise RosExtraMissing(
        f"robocram.ros needs ROS 1 (no {', '.join(missing)}; {INSTALL_HINT}) or ROS 2 "
        f"({SETUP_HINT})"
    )


def require_ros_extra() -> None:
    """Raise :class:`RosExtraMissing` unless every module of the extra is importable."""
    missing = missing_modules()
    if missing:
        raise RosExtraMissing(f"robocram.ros needs {', '.join(missing)}; {INSTALL_HINT}")

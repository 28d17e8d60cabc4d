"""The ROS 2 transport: our rclpy node in a child process (``node_process.py``).

The child runs with the ROS 2 prefix on its path and ROS 1's off it
(``ros2_environment.py``), on the ``ROS_DOMAIN_ID`` of the node's config; the plan
process never imports rclpy. There is no master to ask first: a robot that is absent
shows when a goal's server does not appear within ``ros_server_timeout``.
Entering waits for the robot's first state (discovery takes a moment on ROS 2).
"""

from __future__ import annotations

from robocram.ros.node_process import NodeProcessTransport
from robocram.ros.ros2_environment import child_argv, require_ros2

CHILD_CODE = "from robocram.ros.ros2_node import child_main; child_main()"
FIRST_STATE_TIMEOUT = 5.0  # [s] for the robot's first state after our node started


class Ros2Transport(NodeProcessTransport):
    """rclpy actions, joint states and tf in a child process; see :class:`Transport`."""

    def _launch(self) -> tuple[list[str], dict[str, str]]:
        prefix = require_ros2()
        return child_argv(CHILD_CODE), prefix.environment(self.config.domain_id)

    def _joining(self) -> str:
        return f"ROS 2 domain {self.config.domain_id}"

    def _start(self) -> None:
        """Start the node, then wait (up to ``FIRST_STATE_TIMEOUT``) for the robot's first
        joint states and base transform: ROS 2's discovery takes a moment, and plans read
        the state first. A robot that stays silent shows as its servers' absence later."""
        super()._start()
        self.wait_for_state((0, 0, 0.0), FIRST_STATE_TIMEOUT)

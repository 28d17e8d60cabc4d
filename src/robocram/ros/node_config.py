"""What our ROS node connects to, for either ROS: servers, state topics and time budgets."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class NodeConfig:
    """What the node connects to: servers -> action types, the state topic, timeouts.

    ``ros`` is 1 (``master_uri`` names the ROS master) or 2 (``domain_id`` is the
    ``ROS_DOMAIN_ID``; there is no master).
    """

    master_uri: str
    node_name: str
    servers: dict[str, str]  # server name -> action type, e.g. "control_msgs/PointHead"
    joint_states_topic: str
    base_frame: str  # the robot's base frame, waited for in tf after each motion
    connect_timeout: float  # [s] to wait for an action server to appear
    lost_after: float  # [s] of status silence that count as a lost connection
    clock_skew_bound: float = 0.5  # [s] a larger robot clock offset is reported
    master_timeout: float = 5.0  # [s] for the master to answer before entering fails
    environment_topics: tuple[str, ...] = ()  # joint states of articulated environments
    ros: int = 1
    domain_id: int = 0  # ROS 2's ROS_DOMAIN_ID (0..101)

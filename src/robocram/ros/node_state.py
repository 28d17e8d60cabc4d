"""What a ROS node child process keeps of the robot, whichever ROS it speaks.

The ROS 1 node (rospy) and the ROS 2 node (rclpy) subscribe differently, but keep the same
state for the plan process: the latest joint positions of the robot and of each
environment topic, how many joint-state and base-transform messages have arrived (a
plan-side mark waits for newer ones, never comparing the robot's clock with ours), and
one lock for writing to the plan process.
"""

from __future__ import annotations

import threading
from abc import ABC, abstractmethod
from collections.abc import Iterable
from multiprocessing.connection import Connection

from robocram.ros.node_config import NodeConfig


class NodeState(ABC):
    """The state and the state requests both nodes share (see the module docstring)."""

    def __init__(self, conn: Connection, config: NodeConfig) -> None:
        self.conn = conn
        self.config = config
        self._send_lock = threading.Lock()
        self._state = threading.Condition()
        self._joints: dict[str, float] = {}
        self._joint_arrivals = 0  # joint-state messages received so far
        self._base_arrivals = 0  # transforms of the base frame received so far
        self._environment: dict[str, dict[str, float]] = {t: {} for t in config.environment_topics}

    def send(self, message: tuple[object, ...]) -> None:
        """Write one message to the plan process (from any thread)."""
        with self._send_lock:
            self.conn.send(message)

    def _joints_arrived(self, names: Iterable[str], positions: Iterable[float]) -> bool:
        """Keep a joint-state message's positions; whether it is the first one."""
        with self._state:
            self._joints.update(zip(names, map(float, positions), strict=False))
            self._joint_arrivals += 1
            self._state.notify_all()
            return self._joint_arrivals == 1

    def _environment_arrived(
        self, topic: str, names: Iterable[str], positions: Iterable[float]
    ) -> None:
        with self._state:
            self._environment[topic].update(zip(names, map(float, positions), strict=False))

    def _base_arrived(self) -> None:
        """Count a message holding the base frame's transform (with ``_state`` held)."""
        self._base_arrivals += 1
        self._state.notify_all()

    def _mark(self) -> tuple[int, int]:
        with self._state:
            return (self._joint_arrivals, self._base_arrivals)

    def op_joint_states(self) -> dict[str, float]:
        """The latest joint positions."""
        with self._state:
            return dict(self._joints)

    def op_environment_joint_states(self) -> dict[str, dict[str, float]]:
        """The latest joint positions of each environment topic (empty until heard)."""
        with self._state:
            return {topic: dict(joints) for topic, joints in self._environment.items()}

    def op_snapshot(
        self, target: str, base: str, objects: list[str]
    ) -> tuple[
        dict[str, float],
        dict[str, dict[str, float]],
        dict[str, tuple[tuple[float, ...], tuple[float, ...]]],
    ]:
        """The joints, the environments' joints and the poses in ``target`` of ``base`` and
        of those ``objects`` tf knows (tf2 frames may carry a leading slash), in one reply."""
        known = {frame.lstrip("/") for frame in self.op_frames()}
        sources = [base, *(o for o in objects if o in known and o != base)]
        return (
            self.op_joint_states(),
            self.op_environment_joint_states(),
            self.op_lookups(target, sources),
        )

    @abstractmethod
    def op_frames(self) -> list[str]:
        """Every frame the transforms name (each node's own)."""

    @abstractmethod
    def op_lookups(
        self, target: str, sources: list[str]
    ) -> dict[str, tuple[tuple[float, ...], tuple[float, ...]]]:
        """The poses of ``sources`` in ``target`` (each node's own)."""

    def op_wait_for_state(self, after: tuple[int, int] | None, timeout: float) -> bool:
        """Wait until joint states and a base transform arrived after the mark ``after``
        (None: after this request); no robot stamp is compared with our clock."""
        joints, base = after if after is not None else self._mark()
        with self._state:
            return self._state.wait_for(
                lambda: self._joint_arrivals > joints and self._base_arrivals > base, timeout
            )

"""What a ROS node child process keeps of the robot, whichever ROS it speaks.

The ROS 1 node (rospy) and the ROS 2 node (rclpy) subscribe differently, but keep the same
state for the plan process: the latest joint positions of the robot and of each
environment topic, how many joint-state and base-transform messages have arrived (a
plan-side mark waits for newer ones, never comparing the robot's clock with ours), the
robot's stamps of the latest joint state, environment states and transforms (compared
only with each other: see :meth:`NodeState.op_wait_for_state`), and one lock for writing
to the plan process.

Arrivals alone cannot tell the state after a goal: each topic comes in on its own
connection and thread, so a transform published before the goal ended may be handled
after its result (a loaded machine's tf thread lags behind the joint states by several
messages). When the result's stamp and the joint states share a clock, the stamps decide.
"""

from __future__ import annotations

import threading
from abc import ABC, abstractmethod
from collections.abc import Iterable, Mapping
from multiprocessing.connection import Connection

from robocram.ros.node_config import NodeConfig

AT_END = 1e-6  # [rad | m] joints this near a trajectory's end show the robot standing there
# [s] robot stamps this close are one clock's: a result and the joint states held when it
# came (else, a clock jumped or publishers' clocks apart, the arrivals decide), a state
# stamped this soon after a result, a frame lagging the joints (an older frame is not
# published with them: sent once, or by a machine with another clock)
AFTER_RESULT_WINDOW = 1.0
FIRST_STATE_TIMEOUT = 5.0  # [s] the first snapshot waits this long for a state to come


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
        self._first_snapshot_waited = False  # a snapshot or lookup waited for a first state
        self._environment: dict[str, dict[str, float]] = {t: {} for t in config.environment_topics}
        self._joint_stamp = 0.0  # [s] of the robot's clock; 0: unstamped or none yet
        self._environment_stamps: dict[str, float] = {}  # by topic
        self._frame_stamps: dict[str, float] = {}  # of each moving frame, by child frame

    def send(self, message: tuple[object, ...]) -> None:
        """Write one message to the plan process (from any thread)."""
        with self._send_lock:
            self.conn.send(message)

    def _joints_arrived(
        self, names: Iterable[str], positions: Iterable[float], stamp: float = 0.0
    ) -> bool:
        """Keep a joint-state message's positions and stamp [s]; whether it is the first."""
        with self._state:
            self._joints.update(zip(names, map(float, positions), strict=False))
            self._joint_arrivals += 1
            self._joint_stamp = stamp
            self._state.notify_all()
            return self._joint_arrivals == 1

    def _environment_arrived(
        self, topic: str, names: Iterable[str], positions: Iterable[float], stamp: float = 0.0
    ) -> None:
        with self._state:
            self._environment[topic].update(zip(names, map(float, positions), strict=False))
            self._environment_stamps[topic] = stamp
            self._state.notify_all()

    def _frames_stamped(self, stamps: Iterable[tuple[str, float]]) -> None:
        """Keep the stamps [s] of moving frames' transforms (with ``_state`` held)."""
        self._frame_stamps.update(stamps)
        self._state.notify_all()

    def _base_arrived(self) -> None:
        """Count a message holding the base frame's transform (with ``_state`` held)."""
        self._base_arrivals += 1
        self._state.notify_all()

    def _mark(self, result_stamp: float = 0.0) -> tuple[int, int, float]:
        """The arrivals so far and the robot's stamp [s] of the result being marked, kept
        only if the joint states held are stamped by the same clock (within
        :data:`AFTER_RESULT_WINDOW` of it; else 0.0: the arrivals decide)."""
        with self._state:
            shared = abs(self._joint_stamp - result_stamp) <= AFTER_RESULT_WINDOW
            stamp = result_stamp if result_stamp > 0.0 and shared else 0.0
            return (self._joint_arrivals, self._base_arrivals, stamp)

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
        of those ``objects`` tf knows (tf2 frames may carry a leading slash), in one reply.
        Asked before the robot's first joint state and base transform came, it waits up to
        :data:`FIRST_STATE_TIMEOUT` for them, once: a robot that publishes when its state
        changes (and a lagging tf) may not have sent since our node joined."""
        self._await_first_state()
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

    def _await_first_state(self) -> None:
        """Before the robot's first joint state and base transform came, wait up to
        :data:`FIRST_STATE_TIMEOUT` for them, once: a robot that publishes when its state
        changes (and a lagging tf) may not have sent since our node joined."""
        with self._state:
            if not self._first_snapshot_waited:
                self._first_snapshot_waited = True
                self._state.wait_for(
                    lambda: self._joint_arrivals > 0 and self._base_arrivals > 0,
                    FIRST_STATE_TIMEOUT,
                )

    def op_lookup(self, target: str, source: str) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The latest pose of ``source`` in ``target`` as (position, quaternion)."""
        return self.op_lookups(target, [source])[source]

    def op_lookups(
        self, target: str, sources: list[str]
    ) -> dict[str, tuple[tuple[float, ...], tuple[float, ...]]]:
        """The poses of ``sources`` in ``target``; asked before the first state came, once
        after it (see :meth:`_await_first_state`: a lookup right after our node started
        must not find tf still empty)."""
        self._await_first_state()
        return self._lookups(target, sources)

    @abstractmethod
    def _lookups(
        self, target: str, sources: list[str]
    ) -> dict[str, tuple[tuple[float, ...], tuple[float, ...]]]:
        """The poses of ``sources`` in ``target`` (each node's own)."""

    def op_wait_for_state(
        self,
        after: tuple[int, int, float] | None,
        timeout: float,
        ends_at: Mapping[str, float] | None = None,
    ) -> bool:
        """Wait until the state held is the one after the goal: stamped just after the
        result (:meth:`_stamped_after`), or showing a finished trajectory's end
        (:meth:`_shows_end`); or, if the mark ``after`` (None: this request) has no
        result stamp, joint states and a base transform arrived after it
        (:meth:`_arrived_after`). With a result stamp the arrivals do not count: a
        message handled after the result may have been published before it. No robot
        stamp is compared with our clock."""
        joints, base, result = after if after is not None else self._mark()
        since: list[float] = []  # the stamp of a joint state that arrived after the mark

        def settled() -> bool:
            if ends_at is not None and self._shows_end(ends_at):
                return True
            if result > 0.0 and self._joint_stamp <= result + AFTER_RESULT_WINDOW:
                return self._stamped_after(result)
            return self._arrived_after(joints, base, since)  # no result stamp, or it jumped

        with self._state:
            return self._state.wait_for(settled, timeout)

    def op_settle(
        self,
        after: tuple[int, int, float],
        timeout: float,
        ends_at: Mapping[str, float] | None,
        target: str,
        base: str,
        objects: list[str],
    ) -> (
        tuple[
            dict[str, float],
            dict[str, dict[str, float]],
            dict[str, tuple[tuple[float, ...], tuple[float, ...]]],
        ]
        | None
    ):
        """:meth:`op_wait_for_state`, then :meth:`op_snapshot` in the same reply (None if
        no state came within ``timeout``): a goal's end costs the plan process one request."""
        if not self.op_wait_for_state(after, timeout, ends_at):
            return None
        return self.op_snapshot(target, base, objects)

    def _stamped_after(self, result: float) -> bool:
        """Whether the latest joint state, every moving frame and every environment state
        are stamped at or after the result's stamp ``result`` [s] (within
        :data:`AFTER_RESULT_WINDOW`): the robot reported them after the goal ended, by its
        own clock, in whatever order the topics arrived (call holding ``_state``)."""
        stamp = self._joint_stamp
        if not result <= stamp <= result + AFTER_RESULT_WINDOW:
            return False
        return self._all_stamped_since(result)

    def _arrived_after(self, joints: int, base: int, since: list[float]) -> bool:
        """Whether joint states and a base transform arrived after those counts, with
        every moving frame and environment state stamped no earlier than the first joint
        state seen to arrive after them (kept in ``since``; a stream lagging steadily
        behind the joints catches up with it; unstamped joints: the arrivals alone)
        (call holding ``_state``)."""
        if self._joint_arrivals <= joints:
            return False
        if not since:
            since.append(self._joint_stamp)
        if self._base_arrivals <= base:
            return False
        return since[0] <= 0.0 or self._all_stamped_since(since[0])

    def _all_stamped_since(self, stamp: float) -> bool:
        """Every moving frame and environment state published along (stamped within
        :data:`AFTER_RESULT_WINDOW` before ``stamp`` [s], or later) stamped at ``stamp``
        or later: a stream lagging behind keeps the wait going; a frame sent once, an
        environment unheard or unstamped, or another clock's stamps cannot tell."""
        along = [
            s
            for s in (*self._frame_stamps.values(), *self._environment_stamps.values())
            if s >= stamp - AFTER_RESULT_WINDOW
        ]
        return bool(self._frame_stamps) and all(s >= stamp for s in along)

    def _shows_end(self, ends_at: Mapping[str, float]) -> bool:
        """Whether the latest joint state shows the joints at a finished trajectory's end
        ``ends_at`` (within :data:`AT_END`), and every moving frame's transform and every
        environment state is stamped at or after it, so none of them predates it.

        A robot standing at the end has nothing newer to report, so waiting for the next
        state would only wait for its publishing period. The stamps are the robot's own,
        compared with each other (its clock may be off ours); unstamped states, or a
        publisher whose stamps lag, leave the wait to the arrivals. A real robot's joints
        rarely match so closely, and then the arrivals decide (call holding ``_state``).
        """
        stamp = self._joint_stamp
        if stamp <= 0.0:
            return False
        now = self._joints
        if any(j not in now or abs(now[j] - v) > AT_END for j, v in ends_at.items()):
            return False
        return self._all_stamped_since(stamp)

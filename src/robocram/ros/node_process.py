"""Our ROS node in a child process, spoken to over a pipe (either ROS).

``open(config)`` starts the child, a fresh interpreter running only our node on one end
of a socket pair, and one reader thread that routes replies to the waiting callers and
goal ends to their handles. ``close()`` cancels running goals, asks the node to leave
ROS, joins the reader thread and the process (killing it by PID if it does not end), so
nothing keeps running. If the child dies, every running goal ends LOST and every request
raises, never hangs. ``Ros1Transport`` and ``Ros2Transport`` say how the child starts.
"""

from __future__ import annotations

import contextlib
import itertools
import logging
import socket
import subprocess
import threading
from collections.abc import Mapping, Sequence
from multiprocessing.connection import Connection
from typing import Any, TypeVar

from robocram.ros.errors import RosConnectionLost, RosNodeError
from robocram.ros.node_config import NodeConfig
from robocram.ros.transport import (
    GoalHandle,
    GoalOutcome,
    GoalState,
    RosDict,
    StateMark,
    StateSnapshot,
)
from robocram.tf import Pose

LOG = logging.getLogger("robocram.ros")
START_TIMEOUT = 30.0  # [s] for the child to import its ROS and join
REPLY_TIMEOUT = 10.0  # [s] for a request that does not wait on the robot
STOP_TIMEOUT = 5.0  # [s] for the child to leave ROS before it is killed
T = TypeVar("T", bound="NodeProcessTransport")


class NodeProcessTransport:
    """Our ROS node in a child process, spoken to over a pipe; see :class:`Transport`.

    Subclasses say how the child is started (:meth:`_launch`): the ROS 1 and the ROS 2
    node speak the same pipe protocol (``ros1_node.py``)."""

    def __init__(self, config: NodeConfig, fixed_frame: str = "map") -> None:
        self.config = config
        self.fixed_frame = fixed_frame
        self._ids = itertools.count(1)
        self._cond = threading.Condition()
        self._replies: dict[int, tuple[bool, Any]] = {}
        self._goals: dict[int, GoalHandle] = {}
        self._send_lock = threading.Lock()
        self._dead: str | None = None
        self._conn: Connection | None = None
        self._process: subprocess.Popen[bytes] | None = None
        self._reader: threading.Thread | None = None
        self.node_name = ""
        self.clock_skew: float | None = None  # [s] robot stamps minus our clock, measured once

    def _launch(self) -> tuple[list[str], dict[str, str]]:
        """The child's command line (its pipe's descriptor is appended) and environment."""
        raise NotImplementedError

    def _joining(self) -> str:
        """What the child joins, for errors: a ROS master, a ROS 2 domain."""
        raise NotImplementedError

    @classmethod
    def open(cls: type[T], config: NodeConfig, fixed_frame: str = "map") -> T:
        """Start the node process and wait until it has joined ROS."""
        transport = cls(config, fixed_frame)
        transport._start()
        return transport

    def _on_skew(self, skew: float) -> None:
        """Keep the robot clock's offset; report it when it exceeds the bound."""
        self.clock_skew = skew
        bound = self.config.clock_skew_bound
        if abs(skew) > bound:
            side = "behind" if skew < 0 else "ahead of"
            LOG.warning(
                "the robot's clock is %.3f s %s ours (joint states on %s stamped %+.3f s from "
                "their arrival; bound %.3f s). robocram compares the robot's stamps only with "
                "each other, so results do not change; synchronise the clocks (chrony/ntp) "
                "for stamped data and logs",
                abs(skew), side, self.config.joint_states_topic, skew, bound,
            )  # fmt: skip

    def _start(self) -> None:
        argv, env = self._launch()
        ours, theirs = socket.socketpair()
        self._process = subprocess.Popen(
            [*argv, str(theirs.fileno())], pass_fds=(theirs.fileno(),), env=env
        )
        theirs.close()
        parent = Connection(ours.detach())
        parent.send(self.config)
        self._conn = parent
        if not parent.poll(START_TIMEOUT):
            self._kill()
            raise RosNodeError(
                f"our ROS node did not join {self._joining()} within {START_TIMEOUT} s"
            )
        status, detail = parent.recv()
        while status == "skew":  # the first joint states may come before "ready"
            self._on_skew(float(detail))
            status, detail = parent.recv()
        if status != "ready":
            self._kill()
            raise RosNodeError(f"our ROS node failed to start: {detail}")
        self.node_name = str(detail)
        self._reader = threading.Thread(target=self._read, name="robocram-ros-reader")
        self._reader.start()

    def _read(self) -> None:
        try:
            self._route()
        finally:  # also when a message could not be read: never leave a caller waiting
            self._die("our ROS node process ended")

    def _route(self) -> None:
        assert self._conn is not None
        while True:
            try:
                message = self._conn.recv()
            except (EOFError, OSError):
                return
            if message[0] == "reply":
                _, request_id, ok, payload = message
                with self._cond:
                    self._replies[request_id] = (ok, payload)
                    self._cond.notify_all()
            elif message[0] == "goal":
                _, goal_id, state, text, result, mark, arrived, *feedback = message
                with self._cond:
                    handle = self._goals.pop(goal_id, None)
                if handle is not None:
                    last = feedback[0] if feedback else {}  # the ROS 1 node sends none
                    outcome = GoalOutcome(
                        GoalState(state), text, result, tuple(mark), arrived, last
                    )
                    handle.finish(outcome)
            elif message[0] == "skew":
                self._on_skew(float(message[1]))

    def _die(self, reason: str) -> None:
        with self._cond:
            self._dead = self._dead or reason
            goals, self._goals = list(self._goals.values()), {}
            self._cond.notify_all()
        for handle in goals:
            handle.finish(GoalOutcome(GoalState.LOST, reason, {}))

    def request(self, op: str, *args: Any, timeout: float = REPLY_TIMEOUT) -> Any:
        """Run ``op`` in the node; return its payload or raise what it reported."""
        request_id = next(self._ids)
        self._write((request_id, op, args))
        with self._cond:
            if not self._cond.wait_for(
                lambda: request_id in self._replies or self._dead is not None, timeout
            ):
                raise RosNodeError(f"our ROS node did not answer {op!r} within {timeout} s")
            if request_id not in self._replies:
                raise RosNodeError(f"our ROS node cannot answer {op!r}: {self._dead}")
            ok, payload = self._replies.pop(request_id)
        if not ok:
            raise RosNodeError(f"ROS {op} failed: {payload}")
        return payload

    def _write(self, message: tuple[Any, ...]) -> None:
        if self._conn is None or self._dead is not None:
            raise RosNodeError(f"our ROS node is not running ({self._dead or 'not started'})")
        try:
            with self._send_lock:
                self._conn.send(message)
        except OSError as err:
            self._die(f"pipe to our ROS node broke: {err}")
            raise RosNodeError(f"our ROS node is gone: {err}") from err

    def send_goal(self, server: str, goal: RosDict) -> GoalHandle:
        """Send ``goal`` to ``server``; RosConnectionLost if the server is not there."""
        handle = GoalHandle(next(self._ids), server)
        with self._cond:
            self._goals[handle.goal_id] = handle
        wait = self.config.connect_timeout + REPLY_TIMEOUT
        try:
            handle.sent = self.request("send_goal", handle.goal_id, server, goal, timeout=wait)
        except RosNodeError as err:
            with self._cond:
                self._goals.pop(handle.goal_id, None)
            raise RosConnectionLost(
                f"cannot send a goal to {server}: {err}", server=server, reason=str(err)
            ) from err
        return handle

    def cancel_goal(self, handle: GoalHandle) -> None:
        """Ask the server to cancel ``handle``'s goal."""
        if self._dead is None:
            self.request("cancel", handle.goal_id)

    def wait_for_state(
        self,
        after: StateMark | None,
        timeout: float,
        ends_at: Mapping[str, float] | None = None,
    ) -> bool:
        """Wait for joint states and the base frame's transform arriving after ``after``,
        or for the state held to show a trajectory's end ``ends_at`` (see Transport)."""
        ends = None if ends_at is None else dict(ends_at)
        reply = self.request(
            "wait_for_state", after, timeout, ends, timeout=timeout + REPLY_TIMEOUT
        )
        return bool(reply)

    def settle(
        self,
        after: StateMark,
        timeout: float,
        ends_at: Mapping[str, float] | None,
        snapshot: tuple[str, str, Sequence[str]],
    ) -> StateSnapshot | None:
        """Wait for the state after a goal and read it, in one request (see Transport)."""
        target, base, objects = snapshot
        ends = None if ends_at is None else dict(ends_at)
        reply = self.request(
            "settle",
            after,
            timeout,
            ends,
            target,
            base,
            list(objects),
            timeout=timeout + REPLY_TIMEOUT,
        )
        return None if reply is None else _snapshot(base, reply)

    def joint_states(self) -> dict[str, float]:
        """The latest ``/joint_states`` positions by joint name."""
        return dict(self.request("joint_states"))

    def environment_joint_states(self) -> dict[str, dict[str, float]]:
        """The latest positions on each environment joint-state topic, by topic."""
        return dict(self.request("environment_joint_states"))

    def lookup_transform(self, target_frame: str, source_frame: str) -> Pose:
        """The latest pose of ``source_frame`` in ``target_frame`` from tf2."""
        position, orientation = self.request("lookup", target_frame, source_frame)
        return Pose(tuple(position), tuple(orientation))

    def lookup_transforms(self, target_frame: str, source_frames: Sequence[str]) -> dict[str, Pose]:
        """The latest poses of ``source_frames`` in ``target_frame``, in one request."""
        found = self.request("lookups", target_frame, list(source_frames))
        return {frame: Pose(tuple(p), tuple(q)) for frame, (p, q) in found.items()}

    def frames(self) -> tuple[str, ...]:
        """Every frame in the node's tf2 buffer."""
        return tuple(self.request("frames"))

    def snapshot(self, target_frame: str, base_frame: str, objects: Sequence[str]) -> StateSnapshot:
        """Joints, environment joints, the base's and the known objects' poses, in one request."""
        reply = self.request("snapshot", target_frame, base_frame, list(objects))
        return _snapshot(base_frame, reply)

    def close(self) -> None:
        """Cancel running goals, stop the node process and the reader thread."""
        with self._cond:
            running = list(self._goals.values())
        for handle in running:
            try:
                self.cancel_goal(handle)
            except RosNodeError:
                break
        if self._dead is None:
            with contextlib.suppress(RosNodeError):
                self.request("shutdown")
        self._kill()

    def _kill(self) -> None:
        process = self._process
        if process is not None:
            try:
                process.wait(STOP_TIMEOUT)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
        if self._conn is not None:
            self._conn.close()
        if self._reader is not None and self._reader is not threading.current_thread():
            self._reader.join()


SnapshotReply = tuple[
    dict[str, float],
    dict[str, dict[str, float]],
    dict[str, tuple[tuple[float, float, float], tuple[float, float, float, float]]],
]


def _snapshot(base_frame: str, reply: SnapshotReply) -> StateSnapshot:
    """The node's snapshot reply (joints, environments' joints, poses) as a snapshot."""
    joints, environment, found = reply
    poses = {frame: Pose(p, q) for frame, (p, q) in found.items()}
    base = poses.pop(base_frame)
    return StateSnapshot(dict(joints), dict(environment), base, poses)

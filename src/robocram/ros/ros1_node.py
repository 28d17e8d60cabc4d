"""Our ROS 1 node: runs in a child process and serves the plan process over a pipe.

rospy allows one node per process for the life of the process, with threads that never
end. Running it in a child process started by :class:`Ros1Transport` keeps the plan
process clean: when the environment exits the child leaves ROS and ends, so no thread or
subscriber remains. The node keeps one actionlib client per configured action server,
the latest ``/joint_states``, the latest joint states of the environment's articulated
objects (``environment_topics``, e.g. ``/kitchen/joint_states``: drawers and doors) and
a tf2 buffer fed from ``/tf`` and ``/tf_static``.

The robot's clock is never compared with ours: "the state after a goal" is told by the
robot's stamps compared with each other (the result's and the states'), or, where they
cannot tell, by the joint-state messages and transforms of the base frame that *arrive*
after the goal's result (its ``mark``; ``node_state.py``). The robot clock's offset is
measured once, on the first joint states, and reported to the plan process.

Pipe protocol (tuples of plain values): requests ``(request_id, op, args)``; replies
``("reply", request_id, ok, payload)``; goal ends ``("goal", goal_id, state, text, result,
mark)``; ``("skew", seconds)`` once. A goal whose server publishes no status for
``lost_after`` seconds ends LOST.
"""

from __future__ import annotations

import os
import sys
import threading
import time
from multiprocessing.connection import Connection
from typing import Any

from robocram.ros.errors import RosUnknownKey
from robocram.ros.message_dicts import message_class, to_dict, to_message
from robocram.ros.node_config import NodeConfig
from robocram.ros.node_state import NodeState
from robocram.ros.request_serving import serve_requests
from robocram.ros.transport import GoalState

MONITOR_PERIOD = 0.05  # [s] how often running goals are checked for a silent server
TERMINAL = frozenset(state.value for state in GoalState)
TF_AUTHORITY = "robocram"


class _Server:
    """One action server: its actionlib client, the running goal's handle and when the
    server's status was last heard.

    actionlib's ``ActionClient`` with one goal handle per goal, not ``SimpleActionClient``:
    the simple client shares one state between consecutive goals, and a goal sent right
    after the previous one ended can lose its DONE transition to the old goal's.
    """

    def __init__(self, name: str, action_type: str) -> None:
        import actionlib
        import rospy
        from actionlib_msgs.msg import GoalStatusArray

        self.name = name
        self.action_type = action_type
        self.client = actionlib.ActionClient(name, message_class(f"{action_type}Action"))
        self.handle: Any = None  # actionlib's ClientGoalHandle of the running goal
        self.heard = 0.0  # monotonic [s]
        self.goal_id: int | None = None
        self._status = rospy.Subscriber(f"{name}/status", GoalStatusArray, self._on_status)

    def _on_status(self, _: object) -> None:
        self.heard = time.monotonic()


class RosNode(NodeState):
    """The node's state and request handlers; one instance per child process."""

    def __init__(self, conn: Connection, config: NodeConfig) -> None:
        import rospy
        import tf2_ros
        from sensor_msgs.msg import JointState
        from tf2_msgs.msg import TFMessage

        super().__init__(conn, config)
        self.buffer = tf2_ros.Buffer(cache_time=rospy.Duration(10.0))
        self._tf_subs = [
            rospy.Subscriber("/tf", TFMessage, self._on_tf, callback_args=False),
            rospy.Subscriber("/tf_static", TFMessage, self._on_tf, callback_args=True),
        ]
        self._joint_sub = rospy.Subscriber(config.joint_states_topic, JointState, self._on_joints)
        self._environment_subs = [
            rospy.Subscriber(topic, JointState, self._on_environment, callback_args=topic)
            for topic in config.environment_topics
        ]
        self.servers = {name: _Server(name, kind) for name, kind in config.servers.items()}
        self.running = True

    def _on_joints(self, msg: Any) -> None:
        import rospy

        first = self._joints_arrived(msg.name, msg.position, msg.header.stamp.to_sec())
        if first and not msg.header.stamp.is_zero():  # the robot clock's offset, once
            self.send(("skew", msg.header.stamp.to_sec() - rospy.get_time()))

    def _on_environment(self, msg: Any, topic: str) -> None:
        self._environment_arrived(topic, msg.name, msg.position, msg.header.stamp.to_sec())

    def _on_tf(self, msg: Any, static: bool) -> None:
        """Feed the buffer, then count the arrival if the base frame is in the message."""
        base = False
        for transform in msg.transforms:
            if static:
                self.buffer.set_transform_static(transform, TF_AUTHORITY)
            else:
                self.buffer.set_transform(transform, TF_AUTHORITY)
            base = base or transform.child_frame_id.lstrip("/") == self.config.base_frame
        with self._state:
            if not static:
                self._frames_stamped(
                    (t.child_frame_id.lstrip("/"), t.header.stamp.to_sec()) for t in msg.transforms
                )
            if base:
                self._base_arrived()

    def op_send_goal(self, goal_id: int, server: str, goal: dict[str, object]) -> float:
        """Send a goal once the server is there; its end arrives as a ``goal`` message.
        Returns when it was sent (``time.monotonic()``)."""
        import rospy

        entry = self.servers.get(server)
        if entry is None:
            raise RosUnknownKey(
                f"no action server {server!r} configured; have {sorted(self.servers)}"
            )
        if not entry.client.wait_for_server(rospy.Duration(self.config.connect_timeout)):
            raise ConnectionError(
                f"no action server {server!r} answered within {self.config.connect_timeout} s"
            )
        message = to_message(f"{entry.action_type}Goal", goal)
        entry.heard = time.monotonic()
        with self._state:
            entry.goal_id = goal_id
            entry.handle = entry.client.send_goal(
                message, transition_cb=lambda handle: self._transition(entry, goal_id, handle)
            )
        return time.monotonic()

    def _transition(self, entry: _Server, goal_id: int, handle: Any) -> None:
        """Report the goal's end once its handle is DONE (each goal has its own handle)."""
        from actionlib import CommState

        if handle.get_comm_state() != CommState.DONE:
            return
        arrived = time.monotonic()
        # state arriving from now on, or stamped after the result, shows the end of the goal
        mark = self._mark(_result_stamp(handle))
        with self._state:
            if entry.goal_id != goal_id:
                return
            entry.goal_id, entry.handle = None, None
        code = handle.get_goal_status()
        state = code if code in TERMINAL else GoalState.LOST.value
        result = handle.get_result()
        payload = to_dict(result) if result is not None else {}
        text = handle.get_goal_status_text()
        self.send(("goal", goal_id, state, text, payload, mark, arrived))

    def op_cancel(self, goal_id: int) -> None:
        """Cancel the goal if it still runs."""
        for entry in self.servers.values():
            handle = entry.handle
            if entry.goal_id == goal_id and handle is not None:
                handle.cancel()

    def _lookup(self, target: str, source: str) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The latest pose of ``source`` in ``target`` as (position, quaternion)."""
        import rospy

        t = self.buffer.lookup_transform(target, source, rospy.Time(0)).transform
        return (
            (t.translation.x, t.translation.y, t.translation.z),
            (t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w),
        )

    def _lookups(
        self, target: str, sources: list[str]
    ) -> dict[str, tuple[tuple[float, ...], tuple[float, ...]]]:
        """``_lookup`` of each of ``sources``, in one reply."""
        return {source: self._lookup(target, source) for source in sources}

    def op_frames(self) -> list[str]:
        """Every frame in the tf buffer."""
        return sorted(self.buffer._getFrameStrings())

    def op_shutdown(self) -> None:
        """Leave ROS; the serve loop ends after the reply."""
        self.running = False

    def monitor(self) -> None:
        """End goals whose server has gone silent with LOST (a lost connection)."""
        import rospy

        while self.running and not rospy.is_shutdown():
            now = time.monotonic()
            for entry in self.servers.values():
                goal_id = entry.goal_id
                if goal_id is not None and now - entry.heard > self.config.lost_after:
                    entry.goal_id = None
                    reason = f"no status from {entry.name} for {self.config.lost_after} s"
                    lost = GoalState.LOST.value
                    self.send(("goal", goal_id, lost, reason, {}, self._mark(), now))
            time.sleep(MONITOR_PERIOD)


def _result_stamp(handle: object) -> float:
    """The robot's stamp [s] of the goal's result message (actionlib keeps the last
    ``ActionResult`` on the handle's state machine), 0.0 if there is none."""
    latest = getattr(getattr(handle, "comm_state_machine", None), "latest_result", None)
    to_sec = getattr(getattr(getattr(latest, "header", None), "stamp", None), "to_sec", None)
    return float(to_sec()) if callable(to_sec) else 0.0


def node_main(conn: Connection, config: NodeConfig) -> None:
    """The child process: join ROS, report ready, serve requests until shutdown."""
    os.environ["ROS_MASTER_URI"] = config.master_uri
    try:
        import rospy

        rospy.init_node(config.node_name, anonymous=True, disable_signals=True)
        node = RosNode(conn, config)
    except Exception as err:
        conn.send(("failed", f"{type(err).__name__}: {err}"))
        return
    conn.send(("ready", rospy.get_name()))
    threading.Thread(target=node.monitor, daemon=True).start()
    serve_requests(conn, node)
    rospy.signal_shutdown("robocram environment exited")


def child_main() -> None:
    """The node process's entry (``Ros1Transport``): the pipe's file descriptor is the
    first argument, the :class:`NodeConfig` its first message."""
    conn = Connection(int(sys.argv[1]))
    node_main(conn, conn.recv())

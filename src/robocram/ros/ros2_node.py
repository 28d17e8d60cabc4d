"""Our ROS 2 node: rclpy in a child process, serving the plan process over a pipe.

The same pipe protocol and requests as the ROS 1 node (``ros1_node.py``), so the plan
side is one (``node_process.py``). It runs with the ROS 2 prefix on its path and ROS 1's
taken off (``ros2_environment.py``). It keeps one rclpy ``ActionClient`` per configured
server, the latest joint states, the environments' joint states and the latest transform
of each frame from ``/tf`` and ``/tf_static`` (transient local, as tf2 publishes it),
composed into the poses asked for (``latest_transforms.py``).

ROS 2 differs where the plan side must not see it: an action's result has no status
text, so the controller's words are its ``error_string`` (control_msgs) or ``error_msg``
(Nav2); a server publishes no periodic status, so a goal is LOST when its server leaves
the ROS graph for ``lost_after`` seconds; state arrival is counted as in ROS 1.
"""

from __future__ import annotations

import sys
import threading
import time
from dataclasses import dataclass, field
from multiprocessing.connection import Connection

from robocram.ros.errors import RosUnknownKey
from robocram.ros.latest_transforms import LatestTransforms
from robocram.ros.node_config import NodeConfig
from robocram.ros.node_state import NodeState
from robocram.ros.request_serving import serve_requests
from robocram.ros.ros2_messages import RclpyObject, RosDict, action_class, fill, to_dict
from robocram.ros.tf_cdr import read_stamped_tf_message
from robocram.ros.transport import GoalState

MONITOR_PERIOD = 0.05  # [s]
# action_msgs/GoalStatus numbers -> how the goal ended
STATUS = {4: GoalState.SUCCEEDED, 5: GoalState.PREEMPTED, 6: GoalState.ABORTED}
TF_STATIC_DEPTH = 100


def locked_action_client(node: RclpyObject, action: RclpyObject, name: str) -> RclpyObject:
    """An rclpy ``ActionClient`` whose requests may be sent from any thread.

    rclpy registers a request's sequence number only after sending it: from a thread
    other than the executor's, a quick server's answer could be taken first and dropped
    ("Ignoring unexpected goal response"), leaving the goal hanging. Here sending holds a
    lock that handling an answer waits for, so the number is always registered first.
    """
    from rclpy.action import ActionClient

    class LockedActionClient(ActionClient):
        def __init__(self) -> None:
            super().__init__(node, action, name)
            self.sending = threading.Lock()

        def send_goal_async(self, *args: RclpyObject, **kwargs: RclpyObject) -> RclpyObject:
            with self.sending:
                return super().send_goal_async(*args, **kwargs)

        def _cancel_goal_async(self, *args: RclpyObject, **kwargs: RclpyObject) -> RclpyObject:
            with self.sending:
                return super()._cancel_goal_async(*args, **kwargs)

        def _get_result_async(self, *args: RclpyObject, **kwargs: RclpyObject) -> RclpyObject:
            with self.sending:
                return super()._get_result_async(*args, **kwargs)

        async def execute(self, taken_data: RclpyObject) -> None:
            with self.sending:  # a request being sent now is registered before its answer
                pass
            await super().execute(taken_data)

    return LockedActionClient()


def _seconds(stamp: RclpyObject) -> float:
    """A ``builtin_interfaces/Time`` in seconds."""
    return float(stamp.sec + stamp.nanosec * 1e-9)


@dataclass
class _Server:
    """One action server: its client, the running goal and when the server was last seen."""

    name: str
    action: RclpyObject
    client: RclpyObject
    goal_id: int | None = None
    handle: RclpyObject = None  # rclpy's ClientGoalHandle, once the server accepted the goal
    cancel_pending: bool = False  # cancelled before the server accepted it
    feedback: RosDict = field(default_factory=dict)  # the running goal's last
    seen: float = 0.0  # monotonic [s] the server was last in the ROS graph


class Ros2Node(NodeState):
    """The node's state and request handlers; one instance per child process."""

    def __init__(self, conn: Connection, config: NodeConfig, node: RclpyObject) -> None:
        from rclpy.qos import DurabilityPolicy, QoSProfile
        from sensor_msgs.msg import JointState
        from tf2_msgs.msg import TFMessage

        super().__init__(conn, config)
        self.node = node
        self._transforms = LatestTransforms()
        static = QoSProfile(depth=TF_STATIC_DEPTH, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        # raw: read by tf_cdr.py, 20 times quicker than rclpy's message objects
        node.create_subscription(TFMessage, "/tf", self._on_tf, 100, raw=True)
        node.create_subscription(
            TFMessage, "/tf_static", lambda raw: self._on_tf(raw, static=True), static, raw=True
        )
        node.create_subscription(JointState, config.joint_states_topic, self._on_joints, 10)
        for topic in config.environment_topics:
            node.create_subscription(
                JointState, topic, lambda msg, topic=topic: self._on_environment(msg, topic), 10
            )
        self.servers = {}
        for name, kind in config.servers.items():
            action = action_class(kind)
            self.servers[name] = _Server(name, action, locked_action_client(node, action, name))
        self.running = True

    def _on_joints(self, msg: RclpyObject) -> None:
        stamp = _seconds(msg.header.stamp)
        first = self._joints_arrived(msg.name, msg.position, stamp)
        if first and stamp > 0:  # the robot clock's offset, once
            self.send(("skew", stamp - time.time()))

    def _on_environment(self, msg: RclpyObject, topic: str) -> None:
        self._environment_arrived(topic, msg.name, msg.position, _seconds(msg.header.stamp))

    def _on_tf(self, raw: bytes, static: bool = False) -> None:
        """Keep each frame's latest transform (and a moving one's stamp); count the arrival
        of the base frame's. Only kept here (a robot publishes its tf at 30 Hz or more):
        poses are composed on asking (``latest_transforms.py``)."""
        stamped = read_stamped_tf_message(raw)
        children = [t[1].lstrip("/") for _, t in stamped]
        with self._state:
            self._transforms.update(t for _, t in stamped)
            if not static:
                self._frames_stamped(zip(children, (s for s, _ in stamped), strict=True))
            if self.config.base_frame in children:
                self._base_arrived()

    def op_send_goal(self, goal_id: int, server: str, goal: dict[str, object]) -> float:
        """Send a goal once the server is there; its end arrives as a ``goal`` message."""
        entry = self.servers.get(server)
        if entry is None:
            raise RosUnknownKey(
                f"no action server {server!r} configured; have {sorted(self.servers)}"
            )
        if not entry.client.wait_for_server(timeout_sec=self.config.connect_timeout):
            raise ConnectionError(
                f"no action server {server!r} answered within {self.config.connect_timeout} s"
            )
        message = fill(entry.action.Goal(), goal)
        with self._state:
            entry.goal_id, entry.handle, entry.cancel_pending = goal_id, None, False
            entry.feedback = {}
            entry.seen = time.monotonic()

        future = entry.client.send_goal_async(
            message, feedback_callback=lambda fed: self._on_feedback(entry, goal_id, fed)
        )
        sent = time.monotonic()
        future.add_done_callback(lambda done: self._accepted(entry, goal_id, done.result()))
        return sent

    def _on_feedback(self, entry: _Server, goal_id: int, message: RclpyObject) -> None:
        """Keep the goal's last feedback (Nav2: pose, time, distance remaining)."""
        feedback = to_dict(message.feedback)
        with self._state:
            if entry.goal_id == goal_id:
                entry.feedback = feedback

    def _accepted(self, entry: _Server, goal_id: int, handle: RclpyObject) -> None:
        if not handle.accepted:
            self._finish(entry, goal_id, GoalState.REJECTED, "the server rejected the goal", {})
            return
        with self._state:
            if entry.goal_id != goal_id:
                return
            entry.handle = handle
            cancel = entry.cancel_pending
        if cancel:
            handle.cancel_goal_async()
        result = handle.get_result_async()
        result.add_done_callback(lambda done: self._ended(entry, goal_id, done.result()))

    def _ended(self, entry: _Server, goal_id: int, response: RclpyObject) -> None:
        result = to_dict(response.result)
        state = STATUS.get(response.status, GoalState.LOST)
        text = str(result.get("error_string") or result.get("error_msg") or "")
        self._finish(entry, goal_id, state, text, result)

    def _finish(
        self, entry: _Server, goal_id: int, state: GoalState, text: str, result: RosDict
    ) -> None:
        arrived = time.monotonic()
        mark = self._mark()  # state arriving from now on shows the end of the goal
        with self._state:
            if entry.goal_id != goal_id:
                return
            entry.goal_id, entry.handle = None, None
            feedback = entry.feedback
        self.send(("goal", goal_id, state.value, text, result, mark, arrived, feedback))

    def op_cancel(self, goal_id: int) -> None:
        """Cancel the goal if it still runs (once the server has accepted it)."""
        for entry in self.servers.values():
            with self._state:
                if entry.goal_id != goal_id:
                    continue
                handle = entry.handle
                entry.cancel_pending = handle is None
            if handle is not None:
                handle.cancel_goal_async()

    def _lookups(
        self, target: str, sources: list[str]
    ) -> dict[str, tuple[tuple[float, ...], tuple[float, ...]]]:
        """The poses of ``sources`` in ``target``, in one reply."""
        with self._state:
            poses = self._transforms.lookups(target, sources)
        return {s: (tuple(p.position), tuple(p.orientation)) for s, p in poses.items()}

    def op_frames(self) -> list[str]:
        """Every frame the transforms name."""
        with self._state:
            return self._transforms.frames()

    def op_shutdown(self) -> None:
        """Leave ROS; the serve loop ends after the reply."""
        self.running = False

    def monitor(self) -> None:
        """End goals whose server has left the ROS graph for ``lost_after`` s with LOST."""
        while self.running:
            now = time.monotonic()
            for entry in self.servers.values():
                goal_id = entry.goal_id
                if goal_id is None:
                    continue
                if entry.client.server_is_ready():
                    entry.seen = now
                elif now - entry.seen > self.config.lost_after:
                    reason = f"{entry.name} left the ROS graph for {self.config.lost_after} s"
                    self._finish(entry, goal_id, GoalState.LOST, reason, {})
            time.sleep(MONITOR_PERIOD)


def node_main(conn: Connection, config: NodeConfig) -> None:
    """The child process: join ROS 2, report ready, serve requests until shutdown."""
    try:
        import rclpy
        from rclpy.executors import SingleThreadedExecutor

        context = rclpy.Context()
        rclpy.init(context=context, signal_handler_options=rclpy.SignalHandlerOptions.NO)
        node = rclpy.create_node(config.node_name, context=context)
        executor = SingleThreadedExecutor(context=context)
        executor.add_node(node)
        serving = Ros2Node(conn, config, node)
    except Exception as err:
        conn.send(("failed", f"{type(err).__name__}: {err}"))
        return
    spinning = threading.Thread(target=executor.spin, daemon=True)
    spinning.start()
    conn.send(("ready", node.get_fully_qualified_name()))
    threading.Thread(target=serving.monitor, daemon=True).start()
    serve_requests(conn, serving)
    serving.running = False
    executor.shutdown(timeout_sec=1.0)  # ends spin; rclpy's threads end before the process
    spinning.join(timeout=1.0)
    node.destroy_node()
    rclpy.shutdown(context=context)


def child_main() -> None:
    """The node process's entry (``Ros2Transport``): the pipe's file descriptor is the
    first argument, the :class:`NodeConfig` its first message."""
    conn = Connection(int(sys.argv[1]))
    node_main(conn, conn.recv())

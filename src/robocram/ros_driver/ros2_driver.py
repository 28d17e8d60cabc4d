"""The projection driver as a ROS 2 robot: ros2_control's and Nav2's interfaces, served.

The same goals, faults and controller semantics as the ROS 1 driver
(:class:`ProjectionDriver`), served with rclpy: one ``ActionServer`` per server of the
robot's ROS 2 facts (``/<controller>/follow_joint_trajectory``,
``/<controller>/gripper_cmd``, ``navigate_to_pose``, ...), ``/joint_states`` and ``/tf``
when they changed (looked at ``PUBLISH_RATE`` times a second; at least every
``HEARTBEAT``) and after every goal, before its result and just after it. The tf is a
tree as a real robot's (``tf_frames.py``): on ``/tf_static`` (transient local, as tf2's
static broadcaster) the map's root frame and the robot's fixed joints, on ``/tf`` the
robot's base in ``map``, its moving joints parent -> child and the objects in ``map``.
ROS 2 results carry no status text: a trajectory's words are in ``error_string``,
Nav2's in ``error_msg``. Runs only in a process with the ROS 2 prefix on its path
(``ros2_environment.py``).
"""

from __future__ import annotations

import contextlib
import json
import threading
import time
from collections.abc import Callable
from functools import partial

from robocram.ros.ros2_messages import (
    RclpyObject,
    RosDict,
    action_class,
    fill,
    to_dict,
)
from robocram.ros.tf_cdr import write_tf_message
from robocram.ros_driver import goals
from robocram.ros_driver.motion import Stepper
from robocram.ros_driver.projection_driver import PUBLISH_RATE, Handler, ProjectionDriver, _handler

POLL = 0.02  # [s] how often a faulty goal looks at its cancel request
THREADS = 8  # executor threads: goals of several resources run at once
STATIC_PARENT = "world"  # map's parent on /tf_static
FEEDBACK_PERIOD = 0.1  # [s] between a goal's feedback messages
AFTER_RESULT = 0.003  # [s] after a goal's result, the state is published once more


class Ros2ProjectionDriver(ProjectionDriver):
    """The projection driver's servers and publishers on an rclpy node (``start(node)``)."""

    node: RclpyObject = None

    def start_ros2(self, node: RclpyObject) -> None:
        """Advertise the state topics and start one action server per configured server."""
        from rclpy.action import ActionServer, CancelResponse
        from rclpy.callback_groups import ReentrantCallbackGroup
        from rclpy.qos import DurabilityPolicy, QoSProfile
        from sensor_msgs.msg import JointState
        from tf2_msgs.msg import TFMessage

        self.node = node
        group = ReentrantCallbackGroup()
        static = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self._publishers = {
            "joints": node.create_publisher(JointState, self.config.joint_states_topic, 10),
            "tf": node.create_publisher(TFMessage, "/tf", 100),
            "tf_static": node.create_publisher(TFMessage, "/tf_static", static),
        }
        for environment in self.environments:
            self._publishers[environment] = node.create_publisher(
                JointState, f"/{environment}/joint_states", 10
            )
        served: dict[str, tuple[str, str]] = {}
        for interface in self.config.actions.values():
            served.setdefault(interface.server, (interface.resource, interface.action_type))
        for server, (resource, action_type) in served.items():
            handler = _handler(resource, action_type, self.config, self.controllers)
            self._servers.append(
                ActionServer(
                    node,
                    action_class(action_type),
                    server,
                    execute_callback=partial(self._execute2, server, action_type, handler),
                    cancel_callback=partial(self._on_cancel, server, CancelResponse),
                    callback_group=group,
                )
            )
        self.warm_up()
        self._publish_static()
        threading.Thread(target=self._stream, daemon=True).start()

    def _lag_tf(self, lag: float) -> None:
        """The ROS 2 driver sends its transforms on time (``tf_lag`` is ROS 1's)."""

    def _stream(self) -> None:
        """Publish the state when it changed (a thread of its own: the executor's timers
        cost more than the publishing they would run)."""
        while self.node.context.ok():
            time.sleep(1.0 / PUBLISH_RATE)
            self._publish_if_running(changed_only=True)

    def _on_cancel(self, server: str, response: RclpyObject, _: RclpyObject) -> RclpyObject:
        """Log when a cancel reached the server; accept it unless told to ignore cancels
        (the fault as it is now: a reset may change it)."""
        refuse = self.fault == "ignore_cancel"
        if self.goal_log is not None:
            line = json.dumps({"server": server, "cancel_seen": time.monotonic()})
            with self._log_lock, self.goal_log.open("a") as log:
                log.write(line + "\n")
        return response.REJECT if refuse else response.ACCEPT

    def _record(self, server: str, action_type: str, goal: object) -> None:
        """Append the goal (as the transport's dicts) to the goal log, if there is one."""
        if self.goal_log is None:
            return
        line = json.dumps({"server": server, "action_type": action_type, "goal": to_dict(goal)})
        with self._log_lock, self.goal_log.open("a") as log:
            log.write(line + "\n")

    def _execute2(
        self, server: str, action_type: str, handler: Handler, handle: RclpyObject
    ) -> RclpyObject:
        """Run one goal to its end; returns the result message (rclpy's execute callback)."""
        self._goal_started()
        try:
            return self._execute_counted(server, action_type, handler, handle)
        finally:
            self._goal_finished()

    def _execute_counted(
        self, server: str, action_type: str, handler: Handler, handle: RclpyObject
    ) -> RclpyObject:
        result_type = action_class(action_type).Result
        self._record(server, action_type, handle.request)
        cancelled = lambda: bool(handle.is_cancel_requested)  # noqa: E731
        if self.fault == "ignore_cancel":  # a controller that never stops
            while self.node.context.ok():
                time.sleep(POLL)
            handle.abort()
            return result_type()
        if self.fault == "silent":
            while not cancelled() and self.node.context.ok():
                time.sleep(POLL)
            outcome: goals.Outcome = None
        elif self.fault == "abort":
            outcome = goals.aborted_on_purpose(action_type, bare=True)
        else:
            feedback = _feeder(handle, action_class(action_type).Feedback)
            outcome = self._handle(handler, handle.request, Stepper(self.lock, cancelled), feedback)
        self.goal_ended()
        if outcome is None:
            handle.canceled()
            return result_type()
        succeeded, fields, _ = outcome  # ROS 2 has no status text: the words are in fields
        result = fill(result_type(), _known(result_type(), fields))
        if succeeded:
            handle.succeed()
        else:
            handle.abort()
        self._publish_after_result()
        return result

    def _publish_after_result(self) -> None:
        """Publish the state again just after the result has gone out (rclpy sends it when
        this callback returns), as a robot streaming its state fast would: the client
        waits for state that arrives after the result."""
        later = threading.Timer(AFTER_RESULT, self._publish_if_running)
        later.daemon = True
        later.start()

    def _publish_if_running(self, changed_only: bool = False) -> None:
        """Publish unless the node is shutting down (then a publisher may be gone)."""
        try:
            if not self.node.context.ok():
                return
            if changed_only:
                self.publish_if_changed()
            else:
                self.publish_state()
        except Exception:  # a publisher destroyed under us at shutdown; else a fault
            if self.node.context.ok():
                raise

    def _publish_static(self) -> None:
        """The map's root frame and the robot's fixed joints on /tf_static, in one message
        (latched, depth 1: late subscribers get all of it)."""
        stamp = self._stamp()
        with self.lock:
            fixed = self.tf_frames.static_transforms()
        root = (STATIC_PARENT, "map", (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))  # the identity
        message = write_tf_message((stamp.sec, stamp.nanosec), [root, *fixed])
        self._publishers["tf_static"].publish(message)

    def _stamp(self) -> RclpyObject:
        """Now on the robot's clock (ours + ``clock_offset``) as a ROS 2 Time."""
        from builtin_interfaces.msg import Time

        now = time.time() + self.clock_offset
        return Time(sec=int(now // 1), nanosec=int(now % 1 * 1e9))

    def _publish_state(self) -> None:
        """Publish the joint states and the moving transforms of the tf tree now (one
        publication at a time: ``publish_state``), stamped when the snapshot is taken.

        The transforms go out as CDR bytes written here (``tf_cdr.py``): rclpy's
        message objects would take the driver's time."""
        from sensor_msgs.msg import JointState

        with self.lock:
            joints = self.world.joint_states(self.robot.name)
            transforms = self.tf_frames.moving_transforms()
            environments = {e: self.world.joint_states(e) for e in self.environments}
            self._published_now()
            stamp = self._stamp()
        self._publishers["tf"].publish(write_tf_message((stamp.sec, stamp.nanosec), transforms))
        for environment, values in environments.items():
            self._publishers[environment].publish(_joint_state(JointState, stamp, values))
        self._publishers["joints"].publish(_joint_state(JointState, stamp, joints))


def _joint_state(kind: RclpyObject, stamp: RclpyObject, values: dict[str, float]) -> RclpyObject:
    state = kind(name=list(values), position=[float(v) for v in values.values()])
    state.header.stamp = stamp
    return state


def _feeder(handle: RclpyObject, kind: RclpyObject) -> Callable[[RosDict], None]:
    """Publishes the goal's feedback, at most one message every ``FEEDBACK_PERIOD``."""
    last = [0.0]  # [s] monotonic, when the last one went out

    def feed(fields: RosDict) -> None:
        now = time.monotonic()
        if now - last[0] >= FEEDBACK_PERIOD:
            last[0] = now
            handle.publish_feedback(fill(kind(), fields))

    return feed


def _known(message: RclpyObject, fields: RosDict) -> RosDict:
    """The fields the result type has (a handler's words for ROS 1 may not fit)."""
    have = message.get_fields_and_field_types()
    return {k: v for k, v in fields.items() if k in have}


def serve(driver: Ros2ProjectionDriver, node: RclpyObject, ready: threading.Event) -> None:
    """Spin the node with enough threads for concurrent goals until its context ends."""
    from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor

    executor = MultiThreadedExecutor(num_threads=THREADS, context=node.context)
    executor.add_node(node)
    driver.start_ros2(node)
    driver.publish_state()
    ready.set()
    with contextlib.suppress(ExternalShutdownException):  # SIGTERM, SIGINT
        executor.spin()

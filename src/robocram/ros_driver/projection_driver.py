"""A ROS driver of ours: serves a robot's ROS interfaces by driving a projection world.

For tests and demos the robot behind real ROS is then a simulated one: the action
servers named by the robot's ``ros_action/4`` facts move the projected robot (as
``goals.py`` says per action type), and ``/joint_states`` plus ``/tf`` (a tree as a real
robot's, ``tf_frames.py``: the fixed joints once on ``/tf_static``, latched) are published
when the state changed (looked at ``PUBLISH_RATE`` times a second), at least every
``HEARTBEAT`` while nothing moves, and after every goal, before its result and again
after it, with the joint states of each articulated environment (the
kitchen's drawers and doors) on ``/<name>/joint_states``, as iai_kitchen publishes them.
``fault`` makes every goal end badly on purpose, to exercise clients: ``"silent"`` never
answers (until cancelled), ``"abort"`` aborts with a status text, ``"ignore_cancel"``
never answers and ignores cancels; ``"nan_joint_state"`` publishes the torso's position as NaN.
``controllers="pr2"`` behaves as the real PR2's controllers
(``pr2_controllers.py``: a gripper gap in metres that stalls on objects, joints clamped
to the soft limits, results without status text); ``clock_offset`` [s] shifts the stamps
of everything published (states, transforms, action results, feedback and status), as a
robot clock ahead (+) or behind (-) of ours. Each publication is one snapshot of the
world stamped when it was taken, sent before the next is taken: the stamps on a topic
rise with the state they show. ``tf_lag`` [s] sends the transforms that much late (tests).
:meth:`ProjectionDriver.reset` puts the world back as it was built (``driver_reset.py``).
"""

from __future__ import annotations

import json
import math
import threading
import time
from collections.abc import Callable
from functools import cached_property, partial
from pathlib import Path
from typing import Any

from robocram.motion.robot_geometry import RobotGeometry
from robocram.projection import ProjectedRobot
from robocram.robots import load_description
from robocram.ros.message_dicts import message_class, to_dict, to_message
from robocram.ros.ros_config import RosConfig
from robocram.ros.tf_cdr import Transform
from robocram.ros.transport import RosDict
from robocram.ros_driver import goals, pr2_controllers
from robocram.ros_driver.driver_reset import GOALS_END_TIMEOUT, DriverBusy, DriverSettings
from robocram.ros_driver.errors import DriverArgumentError
from robocram.ros_driver.goals import RosMessage
from robocram.ros_driver.held_handles import HeldHandles
from robocram.ros_driver.lagging_publisher import LaggingPublisher
from robocram.ros_driver.motion import MotionOptions, Stepper
from robocram.ros_driver.robot_clock import RobotClock
from robocram.ros_driver.tf_frames import TfFrames
from robocram.world import RobotObject, World

PUBLISH_RATE = 30.0  # [Hz] how often the state is looked at, and published if it changed
HEARTBEAT = 0.2  # [s] the state is published at least this often, changed or not
# [s] after a goal ends the state streams at PUBLISH_RATE, changed or not: a client may
# get the result after the state published with it and waits for state arriving later
AFTER_GOAL = 0.1
FAULTS = ("none", "silent", "abort", "ignore_cancel", "nan_joint_state")
NAN_JOINT = "torso_lift_joint"  # fault="nan_joint_state": its position is published as NaN
CONTROLLERS = ("projection", "pr2")
Handler = Callable[[Any, goals.GoalContext], goals.Outcome]


def _handler(resource: str, action_type: str, config: RosConfig, controllers: str) -> Handler:
    if action_type.endswith("GripperCommand"):  # control_msgs' or the PR2's Pr2GripperCommand
        arm = resource.removeprefix("gripper(").removesuffix(")")
        if action_type == "control_msgs/ParallelGripperCommand":
            return partial(goals.parallel_gripper_command, semantics=config.grippers[arm])
        if controllers == "pr2":
            return partial(pr2_controllers.gripper_command, arm=arm)
        return partial(goals.gripper_command, semantics=config.grippers[arm])
    if action_type == "pr2_controllers_msgs/SingleJointPosition":
        joint = load_description(config.robot).torso_joint
        if resource != "torso" or joint is None:
            raise DriverArgumentError(
                f"the driver serves SingleJointPosition for a torso, not {resource}"
            )
        return partial(goals.single_joint_position, joint=joint)
    return {
        "move_base_msgs/MoveBase": goals.move_base,
        "nav2_msgs/NavigateToPose": goals.navigate_to_pose,
        "control_msgs/FollowJointTrajectory": goals.follow_joint_trajectory,
        "pr2_controllers_msgs/JointTrajectory": goals.follow_joint_trajectory,
        "control_msgs/PointHead": goals.point_head,
        "pr2_controllers_msgs/PointHead": goals.point_head,
        "robocram_msgs/DetectObjects": goals.detect_objects,
    }[action_type]


def _result(result_type: str, fields: dict[str, object]) -> RosMessage:
    """The result message with the fields its type has (the PR2's trajectory results have
    none: their controllers report only by the goal status)."""
    slots = message_class(result_type).__slots__
    return to_message(result_type, {k: v for k, v in fields.items() if k in slots})


class ProjectionDriver:
    """The action servers and state publishers of one projected robot (call ``start``)."""

    def __init__(
        self,
        world: World,
        config: RosConfig,
        options: MotionOptions | None = None,
        fault: str = "none",
        goal_log: Path | None = None,
        controllers: str = "projection",
        clock_offset: float = 0.0,
        tf_lag: float = 0.0,
    ) -> None:
        """``goal_log``: a file each received goal is appended to, one JSON line
        ``{"server", "action_type", "goal"}`` (goal as message dicts), before it runs.
        ``controllers``: ``"projection"`` or ``"pr2"``; ``clock_offset``, ``tf_lag`` [s]."""
        if fault not in FAULTS:
            raise DriverArgumentError(f"driver fault {fault!r} is none of {FAULTS}")
        if controllers not in CONTROLLERS:
            raise DriverArgumentError(
                f"driver controllers {controllers!r} are none of {CONTROLLERS}"
            )
        self.controllers = controllers
        self.clock_offset = clock_offset
        self.clock = RobotClock(clock_offset)
        self.tf_lag = tf_lag
        self._publishing = threading.Lock()  # one publication at a time, in snapshot order
        self.world = world
        self.robot = ProjectedRobot.of(world, config.robot)
        self.config = config
        self.options = options or MotionOptions()
        self.fault = fault
        self.lock = threading.Lock()
        self.handles = HeldHandles()  # a drawer follows the hand holding its handle
        self.environments = [  # articulated objects that are not robots: kitchens, cupboards
            o.name
            for o in world.objects()
            if not isinstance(o, RobotObject) and world.joint_states(o)
        ]
        self.soft_limits = (
            pr2_controllers.soft_limits(self.robot.description.urdf)
            if controllers == "pr2"
            else None
        )
        self._servers: list[Any] = []
        self._publishers: dict[str, Any] = {}
        self.goal_log = goal_log
        self._log_lock = threading.Lock()
        self._published: tuple[object, ...] | None = None  # the state last published
        self._published_at = -math.inf  # [s] monotonic
        self._streaming_until = -math.inf  # [s] monotonic: AFTER_GOAL after the last goal
        self._built = world.snapshots.capture()  # what a reset puts back
        self._running = 0  # goals being executed
        self._goals_ended = threading.Condition()

    def reset(self, settings: DriverSettings, timeout: float = GOALS_END_TIMEOUT) -> None:
        """Once no goal runs (else :class:`DriverBusy` after ``timeout`` [s]), put the
        world back as it was built, let go of every handle, take ``settings`` and publish:
        the driver then serves what one just started with ``settings`` would."""
        if settings.fault not in FAULTS:
            raise DriverArgumentError(f"driver fault {settings.fault!r} is none of {FAULTS}")
        with self._goals_ended:
            if not self._goals_ended.wait_for(lambda: self._running == 0, timeout):
                raise DriverBusy(f"{self._running} goal(s) still running after {timeout} s")
        with self.lock:
            self.world.snapshots.restore(self._built)
            self.robot = ProjectedRobot.of(self.world, self.config.robot)
            self.handles = HeldHandles()
            self.options = MotionOptions(
                base_speed=settings.base_speed, time_scale=settings.time_scale
            )
            self.fault = settings.fault
            self.goal_log = settings.goal_log_path
            self.clock_offset = self.clock.offset = settings.clock_offset
            self._lag_tf(settings.tf_lag)
            self._published = None
            self._streaming_until = -math.inf
        self.publish_state()

    def _lag_tf(self, lag: float) -> None:
        """Send the transforms ``lag`` [s] late from now on (ROS 1's ``/tf``)."""
        if lag == self.tf_lag:
            return
        tf = self._publishers["tf"]
        plain = tf.publisher if isinstance(tf, LaggingPublisher) else tf
        self._publishers["tf"] = LaggingPublisher(plain, lag) if lag > 0.0 else plain
        self.tf_lag = lag

    def _goal_started(self) -> None:
        with self._goals_ended:
            self._running += 1

    def _goal_finished(self) -> None:
        with self._goals_ended:
            self._running -= 1
            self._goals_ended.notify_all()

    def warm_up(self) -> None:
        """Build the robot's kinematics and collision geometry now, before serving, as a
        simulator loads its robot: else the first goal checked for collisions pays for
        them (a third of the driver's time in a kitchen transport)."""
        self.robot.description.model.derived(RobotGeometry.of)

    def start(self) -> None:
        """Advertise the state topics and start one action server per configured server."""
        import actionlib
        import rospy
        from sensor_msgs.msg import JointState
        from tf2_msgs.msg import TFMessage

        self._publishers = {
            "joints": rospy.Publisher(self.config.joint_states_topic, JointState, queue_size=10),
            "tf": rospy.Publisher("/tf", TFMessage, queue_size=10),
            "tf_static": rospy.Publisher("/tf_static", TFMessage, queue_size=1, latch=True),
        }
        if self.tf_lag > 0.0:
            self._publishers["tf"] = LaggingPublisher(self._publishers["tf"], self.tf_lag)
        for environment in self.environments:
            self._publishers[environment] = rospy.Publisher(
                f"/{environment}/joint_states", JointState, queue_size=10
            )
        served: dict[str, tuple[str, str]] = {}
        for interface in self.config.actions.values():
            served.setdefault(interface.server, (interface.resource, interface.action_type))
        for server, (resource, action_type) in served.items():
            action = actionlib.SimpleActionServer(
                server, message_class(f"{action_type}Action"), auto_start=False
            )
            handler = _handler(resource, action_type, self.config, self.controllers)
            action.register_goal_callback(
                partial(self._on_goal, action, server, action_type, handler)
            )
            action.register_preempt_callback(partial(self._on_preempt, server))
            action.start()
            self.clock.stamp_actions(action)
            self._servers.append(action)
        self.warm_up()
        self._publish_static()
        rospy.Timer(rospy.Duration(1.0 / PUBLISH_RATE), lambda _: self.publish_if_changed())

    def _on_goal(self, server: Any, name: str, action_type: str, handler: Handler) -> None:
        goal = server.accept_new_goal()
        self._record(name, action_type, goal)
        self._goal_started()
        threading.Thread(
            target=self._counted, args=(server, action_type, handler, goal), daemon=True
        ).start()

    def _counted(
        self, server: RosMessage, action_type: str, handler: Handler, goal: RosMessage
    ) -> None:
        try:
            self._execute(server, action_type, handler, goal)
        finally:
            self._goal_finished()

    def _on_preempt(self, server: str) -> None:
        """Log when a cancel reached the server (``time.monotonic()``, for benchmarks)."""
        if self.goal_log is None:
            return
        line = json.dumps({"server": server, "cancel_seen": time.monotonic()})
        with self._log_lock, self.goal_log.open("a") as log:
            log.write(line + "\n")

    def _record(self, server: str, action_type: str, goal: object) -> None:
        """Append the goal to the goal log, if there is one."""
        if self.goal_log is None:
            return
        line = json.dumps({"server": server, "action_type": action_type, "goal": to_dict(goal)})
        with self._log_lock, self.goal_log.open("a") as log:
            log.write(line + "\n")

    def _execute(self, server: Any, action_type: str, handler: Handler, goal: RosMessage) -> None:
        import rospy

        stepper = Stepper(self.lock, server.is_preempt_requested)
        result_type = f"{action_type}Result"
        if self.fault == "ignore_cancel":  # a controller that never stops
            while not rospy.is_shutdown():
                rospy.sleep(0.02)
            return
        if self.fault == "silent":
            while not server.is_preempt_requested() and not rospy.is_shutdown():
                rospy.sleep(0.02)
            outcome: goals.Outcome = None
        elif self.fault == "abort":
            outcome = goals.aborted_on_purpose(action_type, bare=self.controllers == "pr2")
        else:
            outcome = self._handle(handler, goal, stepper)
        self.goal_ended()
        if outcome is None:
            server.set_preempted(to_message(result_type, {}), "cancelled; stopped where it was")
        else:
            succeeded, result, text = outcome
            message = _result(result_type, result)
            if succeeded:
                server.set_succeeded(message, text)
            else:
                server.set_aborted(message, text)
        self.publish_state()  # stamped after the result, as a robot streaming its state is

    def _handle(
        self,
        handler: Handler,
        goal: RosMessage,
        stepper: Stepper,
        feedback: Callable[[RosDict], None] = lambda _: None,
    ) -> goals.Outcome:
        """Run the handler; an error in it aborts the goal with the error as status text."""
        try:
            context = goals.GoalContext(
                self.robot, self.options, stepper, self.soft_limits, self.handles, feedback
            )
            return handler(goal, context)
        except Exception as err:  # reported to the client, never a goal left hanging
            return False, {}, f"driver error: {type(err).__name__}: {err}"

    def publish_if_changed(self) -> None:
        """Publish the state if it changed since it was last published, or if the last
        was ``HEARTBEAT`` ago: a robot standing still sends a slow stream, one moving
        sends every change at ``PUBLISH_RATE``; for ``AFTER_GOAL`` after a goal ended
        (:meth:`goal_ended`) every look publishes, changed or not."""
        with self.lock:
            state = self._fingerprint()
        now = time.monotonic()
        if (
            state == self._published
            and now - self._published_at < HEARTBEAT
            and now > self._streaming_until
        ):
            return
        self.publish_state()

    def goal_ended(self) -> None:
        """Publish the state now and stream it for ``AFTER_GOAL`` (call as a goal ends)."""
        self._streaming_until = time.monotonic() + AFTER_GOAL
        self.publish_state()

    def _fingerprint(self) -> tuple[object, ...]:
        """What the published state follows from: the joints of the robot and of the
        environments and every object's pose (call holding ``lock``; ~0.1 ms)."""
        world = self.world
        return (
            tuple(world.joint_states(self.robot.name).values()),
            tuple(tuple(world.joint_states(e).values()) for e in self.environments),
            tuple(world.pose(obj) for obj in world.objects()),
        )

    def _published_now(self) -> None:
        """Note the state being published (call holding ``lock``)."""
        self._published = self._fingerprint()
        self._published_at = time.monotonic()

    @cached_property
    def tf_frames(self) -> TfFrames:
        """The world's frames as a tree: which are fixed, which move."""
        return TfFrames(self.world)

    def publish_state(self) -> None:
        """Publish the joint states and the moving transforms of the tf tree now.

        The snapshot is stamped when taken and sent before the next is taken: else a
        publisher thread held up between the two (a loaded machine) sends a state from
        before a goal's end, stamped after it, after the goal's result."""
        with self._publishing:
            self._publish_state()

    def _publish_state(self) -> None:
        from sensor_msgs.msg import JointState
        from tf2_msgs.msg import TFMessage

        with self.lock:
            joints = self.world.joint_states(self.robot.name)
            moving = self.tf_frames.moving_transforms()
            environments = {e: self.world.joint_states(e) for e in self.environments}
            self._published_now()
            stamp = self.clock.now()
        if self.fault == "nan_joint_state" and NAN_JOINT in joints:  # an encoder gone bad
            joints = {**joints, NAN_JOINT: math.nan}
        state = JointState(name=list(joints), position=list(joints.values()))
        state.header.stamp = stamp
        self._publishers["tf"].publish(TFMessage(transforms=_stamped(stamp, moving)))
        for environment, values in environments.items():
            message = JointState(name=list(values), position=list(values.values()))
            message.header.stamp = stamp
            self._publishers[environment].publish(message)
        self._publishers["joints"].publish(state)

    def _publish_static(self) -> None:
        """The robot's fixed joints on /tf_static, latched, in one message (as tf2's
        static broadcaster sends them)."""
        from tf2_msgs.msg import TFMessage

        stamp = self.clock.now()
        fixed = self.tf_frames.static_transforms()
        self._publishers["tf_static"].publish(TFMessage(transforms=_stamped(stamp, fixed)))


def _stamped(stamp: object, transforms: list[Transform]) -> list[object]:
    """rospy's ``TransformStamped`` of each transform, all stamped ``stamp``."""
    from geometry_msgs.msg import TransformStamped

    out = []
    for parent, child, translation, rotation in transforms:
        t = TransformStamped()
        t.header.stamp, t.header.frame_id, t.child_frame_id = stamp, parent, child
        t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = (
            translation
        )
        r = t.transform.rotation
        r.x, r.y, r.z, r.w = rotation
        out.append(t)
    return out

"""The plan side of one robot behind ROS: its description, ROS facts and transport.

Process modules ask it to run goals on resources, to move joints by timed trajectories
(``motion_planner.py``) and to read the robot's state. After a
goal ends it waits for the first joint states and transforms published after the
result, so what a plan reads next (tool poses, joint values) shows the end of the motion;
with a world, the world is then put into that state (``world_mirror.py``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

from robocram.motion import JointTrajectory, MotionSettings, report_executed
from robocram.robots import ArmDescription, LoadedDescription
from robocram.ros.coupled_trajectory import with_coupled_followers
from robocram.ros.errors import (
    RosCancelIgnored,
    RosCommandError,
    RosConnectionLost,
    RosJointStateInvalid,
    RosNodeError,
)
from robocram.ros.goal_runner import Accept, FailureFactory, checked, finish_goal
from robocram.ros.motion_planner import MotionPlanner, clamp_goal
from robocram.ros.node_config import NodeConfig
from robocram.ros.ros1_transport import Ros1Transport
from robocram.ros.ros2_transport import Ros2Transport
from robocram.ros.ros_config import RosConfig
from robocram.ros.trajectory_goal import trajectory_goal
from robocram.ros.transport import (
    GoalOutcome,
    GoalState,
    RosDict,
    StateMark,
    StateSnapshot,
    Transport,
)
from robocram.ros.world_mirror import WorldMirror, environment_topics
from robocram.tf import Pose, PoseLike, PoseStamped
from robocram.world import World

STATE_TIMEOUT = 5.0  # [s] for the state after a goal to arrive
FIRST_STATE: StateMark = (0, 0, 0.0)  # a mark before anything arrived: any state is after it
DEFAULT_MASTER_TIMEOUT = 5.0  # [s] for the ROS master to answer when entering
RESOURCE_KINDS = {"torso": "torso", "head": "head"}  # a trajectory's kind; arms': "arm"
TransportFactory = Callable[[NodeConfig], Transport]
TRANSPORTS: dict[int, TransportFactory] = {1: Ros1Transport.open, 2: Ros2Transport.open}


class RosRobotClient:
    """One robot's ROS connection for process modules; ``connect`` / ``disconnect``."""

    def __init__(
        self,
        desc: LoadedDescription,
        config: RosConfig,
        master_uri: str,
        node_name: str = "robocram",
        fixed_frame: str = "map",
        transport_factory: TransportFactory | None = None,
        world: World | None = None,
        motion: MotionSettings | None = None,
        master_timeout: float = DEFAULT_MASTER_TIMEOUT,
        ros: int = 1,
        domain_id: int = 0,
    ) -> None:
        """``world``: a projection world of the robot's environment to plan motions in
        (kept in sync with the robot's state); None plans straight joint moves.
        ``master_timeout`` [s]: how long ``connect`` waits for the ROS master to answer.
        ``ros``: 1 or 2 (the transport, unless ``transport_factory`` is given);
        ``domain_id``: ROS 2's ``ROS_DOMAIN_ID``."""
        self.desc = desc
        self.config = config
        self.fixed_frame = fixed_frame
        self.mirror = (
            WorldMirror(world, desc, environment_topics(world, config.environment_topics))
            if world is not None
            else None
        )
        self.node_config = NodeConfig(
            master_uri=master_uri,
            node_name=node_name,
            servers=config.servers(),
            joint_states_topic=config.joint_states_topic,
            base_frame=desc.base_frame,
            connect_timeout=config.server_timeout,
            lost_after=config.connection_timeout,
            clock_skew_bound=config.clock_skew_bound,
            master_timeout=master_timeout,
            environment_topics=tuple(self.mirror.topics.values()) if self.mirror else (),
            ros=ros,
            domain_id=domain_id,
        )
        self._factory = transport_factory or TRANSPORTS[ros]
        self._transport: Transport | None = None
        self._planner = MotionPlanner(desc, world, motion)
        self.unconfirmed_cancels: list[RosCancelIgnored] = []

    @property
    def name(self) -> str:
        """The robot's name."""
        return self.desc.name

    def connect(self) -> None:
        """Start the transport (our ROS node)."""
        if self._transport is not None:
            raise RosNodeError(f"{self.name}'s ROS connection is already open")
        self._transport = self._factory(self.node_config)

    def disconnect(self) -> None:
        """Stop the transport; nothing of it keeps running."""
        transport, self._transport = self._transport, None
        if transport is not None:
            transport.close()

    @property
    def clock_skew(self) -> float | None:
        """[s] the robot's stamps minus our clock, once measured (None before, or unknown)."""
        return getattr(self._transport, "clock_skew", None)

    @property
    def transport(self) -> Transport:
        """The open transport, or a RosNodeError saying where to run."""
        if self._transport is None:
            raise RosNodeError(
                f"{self.name}'s ROS connection is not open; perform inside ros_robot(...)"
            )
        return self._transport

    def run(
        self,
        resource: str,
        goal: RosDict,
        failure: FailureFactory,
        accept: Accept | None = None,
        ends_at: Mapping[str, float] | None = None,
    ) -> GoalOutcome:
        """Run ``goal`` on ``resource``'s action server, then wait for the state after it.

        ``accept(outcome)`` says whether an outcome other than SUCCEEDED is a success too
        (a PR2 gripper holding an object ends ABORTED with ``stalled``). ``ends_at``: the
        joint values a trajectory goal ends at (see :meth:`Transport.wait_for_state`).
        """
        interface = self.config.action(resource)
        settle = lambda end: self._settle(interface.server, end, ends_at)  # noqa: E731
        try:
            outcome = finish_goal(self.transport, interface, goal, settle)
        except RosCancelIgnored as ignored:
            if ignored.stopping:  # a stopped task's failure may be dropped (pursue): keep it
                self.unconfirmed_cancels.append(ignored)
            raise
        return checked(interface, outcome, failure, accept)

    def raise_unconfirmed_cancel(self) -> None:
        """Raise the first cancel a server did not confirm (the robot may still be moving),
        if any; called when a ``ros_robot`` block ends without an error of its own."""
        if self.unconfirmed_cancels:
            first = self.unconfirmed_cancels[0]
            raise RosCancelIgnored(
                f"{first.message}; it happened in a task that was stopped, so the block "
                "ended without it",
                server=first.server,
                timeout=first.timeout,
                stopping=True,
            )

    def _settle(
        self, server: str, end: GoalOutcome, ends_at: Mapping[str, float] | None = None
    ) -> None:
        """Wait for the state published after ``end`` (failed goals moved the robot too)
        and put the world in it; a succeeded trajectory's state may show its end
        ``ends_at`` already."""
        shown = ends_at if end.state is GoalState.SUCCEEDED else None
        mirror = self.mirror
        if mirror is None:
            settled = self.transport.wait_for_state(end.mark, STATE_TIMEOUT, shown)
        else:
            read = (self.fixed_frame, self.desc.base_frame, mirror.movable_objects())
            state = self.transport.settle(end.mark, STATE_TIMEOUT, shown, read)
            if settled := state is not None:
                self._sync(mirror, state)
        if not settled:
            raise RosConnectionLost(
                f"no joint states or transforms of {self.name} arrived within {STATE_TIMEOUT} s "
                f"after {server} finished",
                server=server,
                reason="state not published",
            )

    @property
    def has_world(self) -> bool:
        """Whether motions are planned in a world of the robot's environment."""
        return self._planner.world is not None

    def planner(self) -> MotionPlanner:
        """The motion planner, its world (if any) put where ROS says the robot is now."""
        self.mirror_state()
        return self._planner

    def mirror_state(self) -> None:
        """Put the world (if any) into the state ROS reports now: the robot's joints and
        base, the environments' joints and the poses of the objects tf knows."""
        mirror = self.mirror
        if mirror is None:
            return
        state = self.transport.snapshot(
            self.fixed_frame, self.desc.base_frame, mirror.movable_objects()
        )  # one request
        self._sync(mirror, state)

    def _sync(self, mirror: WorldMirror, state: StateSnapshot) -> None:
        mirror.sync(self._finite(state.joints), state.base, state.environment, state.objects)

    def move_joints(
        self,
        resource: str,
        goal: Mapping[str, float],
        failure: FailureFactory,
        *,
        arm: str | None = None,
        mode: str = "avoid_all",
        touching: str | None = None,
    ) -> JointTrajectory:
        """Move the joints of ``goal`` [rad | m] there by a timed trajectory on ``resource``;
        under ``allow_hand`` the hand may touch ``touching`` within its bound.

        The trajectory is planned by :class:`MotionPlanner` (checked in the world if one
        was given; the torso's straight only, as in projection) and named by the
        resource (kind ``torso``, ``head``, else ``arm``). A goal outside the joint limits
        is clamped, sent, and then raises ``failure`` naming the joints, as projection does.

        Raises:
            ManipulationPathBlocked: the world blocks the way; nothing was sent.
        """
        clamped = clamp_goal(self.desc, goal)
        current = self.joint_states()
        missing = sorted(j for j in clamped.goal if j not in current)
        if missing:
            raise RosCommandError(
                f"{self.name}'s joint states on {self.config.joint_states_topic} lack {missing}; "
                "check the topic in ros_topic/3 and the robot's driver"
            )
        what = f"{self.name}'s {arm} arm" if arm is not None else f"{self.name}'s {resource}"
        trajectory = self.planner().joint_motion(
            clamped.goal, current, arm=arm, mode=mode, what=what,
            kind=RESOURCE_KINDS.get(resource, "arm"), plan=resource != "torso", touching=touching,
        )  # fmt: skip
        self.follow_trajectory(resource, trajectory, failure)
        if clamped.culprits:
            raise failure(clamped.describe(self.name))
        return trajectory

    def follow_trajectory(
        self, resource: str, trajectory: JointTrajectory, failure: FailureFactory
    ) -> GoalOutcome:
        """Send ``trajectory`` as the goal of ``resource``'s action type, then check the
        joints reached against the goal tolerances; report it to the trajectory listeners.

        ``control_msgs/FollowJointTrajectory`` goals carry the tolerances of the robot's
        facts; the PR2's native ``JointTrajectory`` takes the trajectory alone and
        ``SingleJointPosition`` the last position and the duration. Joints coupled to an
        actuator in it (Stretch's telescope) are sent with it. Whatever the type,
        a joint ending beyond its tolerance raises ``failure`` naming it.
        """
        interface = self.config.action(resource)
        if interface.action_type != "pr2_controllers_msgs/SingleJointPosition":
            trajectory = with_coupled_followers(self.desc, trajectory)
        goal = trajectory_goal(interface.action_type, trajectory, self.config.goal_tolerances)
        outcome = self.run(resource, goal, failure, ends_at=trajectory.end)
        self._check_reached(trajectory, failure)
        report_executed(trajectory)
        return outcome

    def _check_reached(self, trajectory: JointTrajectory, failure: FailureFactory) -> None:
        reached = self.joint_states()
        tolerances = self.config.goal_tolerances
        beyond = {
            joint: (reached[joint], goal, tolerances.position(joint))
            for joint, goal in trajectory.end.items()
            if joint in reached and abs(reached[joint] - goal) > tolerances.position(joint)
        }
        if beyond:
            raise failure(
                f"{self.name}'s joints ended beyond their goal tolerances (reached, goal, "
                f"tolerance): {beyond}; the controller reported success"
            )

    def joint_states(self) -> dict[str, float]:
        """The latest joint positions [rad | m]; before the robot's first joint state has
        come, up to ``STATE_TIMEOUT`` for it (a robot that publishes when its state changes
        may not have published since our node joined).

        Raises:
            RosJointStateInvalid: a position is not a finite number (naming the topic
                and the joint): a plan must not start from it.
        """
        states = self.transport.joint_states()
        if not states:
            self.transport.wait_for_state(FIRST_STATE, STATE_TIMEOUT)
            states = self.transport.joint_states()
        return self._finite(states)

    def _finite(self, states: dict[str, float]) -> dict[str, float]:
        """``states``, checked: every position a finite number.

        Raises:
            RosJointStateInvalid: naming the topic and the joint.
        """
        for joint, value in states.items():
            if not math.isfinite(value):
                topic = self.config.joint_states_topic
                raise RosJointStateInvalid(
                    f"{self.name} reported {joint!r} at {value} on {topic}",
                    topic=topic,
                    joint=joint,
                    value=value,
                )
        return states

    def actuated_joint_states(self) -> dict[str, float]:
        """The latest positions of the joints that are not mimic joints (IK and FK seeds)."""
        model = self.desc.model
        return {
            joint: value
            for joint, value in self.joint_states().items()
            if model is None or (joint in model.joints and model.joints[joint].mimic is None)
        }

    def arm(self, arm: str) -> ArmDescription:
        """The arm called ``arm`` (or on that side), or a RosCommandError naming the arms."""
        spec = self.desc.arms.get(self.desc.arm_called(arm))
        if spec is None or arm == self.desc.neck_arm:
            arms = sorted(a for a in self.desc.arms if a != self.desc.neck_arm)
            raise RosCommandError(f"{self.name} has no arm {arm!r}; its arms are {arms}")
        return spec

    def frame_pose(self, frame: str) -> Pose:
        """The latest pose of ``frame`` in the fixed frame."""
        if frame == self.fixed_frame:
            return Pose()
        return self.transport.lookup_transform(self.fixed_frame, frame)

    def base_pose(self) -> Pose:
        """The robot base's pose in the fixed frame."""
        return self.frame_pose(self.desc.base_frame)

    def in_map(self, pose: PoseStamped | PoseLike) -> Pose:
        """A stamped pose (any tf frame) or a plain pose (the fixed frame) in the fixed frame."""
        if isinstance(pose, PoseStamped):
            return self.frame_pose(pose.frame_id) * pose.pose
        return Pose.coerce(pose)

"""The process modules of a robot behind ROS: one per motion table resource, sending goals.

Each executes the motion table's commands of its resource (one method per command, as
projection's modules do): ``move_base``, ``move_torso``, ``move_head``, ``detect`` and
``inspect``, ``move_gripper_joint``; the arms are in ``arm_module.py``. Which action
server serves a resource comes from the robot's ROS facts (``ros_config.py``).
"""

from __future__ import annotations

import numpy as np

from robocram.designators import ObjectDesignator, Quantifier
from robocram.designators.perceived_object import PerceivedObject
from robocram.execution import MotionProcessModule
from robocram.execution.failures import (
    ManipulationPathBlocked,
    NavigationGoalNotReached,
    PerceptionObjectNotFound,
    PtuGoalNotReached,
    PtuPathBlocked,
    TorsoGoalNotReached,
    TorsoPathBlocked,
)
from robocram.logic import Value
from robocram.motion.tool_goal import joint_values
from robocram.robots.looking_means import head_joints
from robocram.ros.errors import RosCommandError, RosUsageError
from robocram.ros.gripper_goal import move_gripper
from robocram.ros.head_aim import pan_tilt_towards
from robocram.ros.ros_robot_client import RosRobotClient
from robocram.tf import Pose, PoseLike, PoseStamped, pose_stamped_from_ros, pose_to_ros

DIRECTION_REACH = 100.0  # [m] looking along a direction aims at a point this far away
POINTING_AXIS = {"x": 0.0, "y": 0.0, "z": 1.0}  # the optical axis of camera frames


class RosProcessModule(MotionProcessModule):
    """A process module of a robot behind ROS, for one resource of the motion table."""

    def __init__(self, client: RosRobotClient) -> None:
        super().__init__()
        self.client = client


class NavigationPM(RosProcessModule):
    """The base over ``move_base_msgs/MoveBase`` (ROS 1) or Nav2's
    ``nav2_msgs/NavigateToPose`` (ROS 2): ``move_base(Pose)``."""

    name = "ros_navigation"
    resource = "navigation"

    def move_base(self, target: PoseStamped | PoseLike) -> Pose:
        """Send a MoveBase or NavigateToPose goal; return the base pose reached.

        The robot plans its own path; with a world given to ``ros_robot``, the path is
        first checked there (``plan_base_path``), and no goal is sent if none exists.

        Raises:
            NavigationPathBlocked: no path to the goal in the world (nothing was sent).
            NavigationPoseUnreachable: the robot would collide at the goal in the world.
        """
        goal_in_map = self.client.in_map(target)
        self.client.planner().base_path(goal_in_map)
        return send_base_goal(self.client, goal_in_map)


def send_base_goal(client: RosRobotClient, goal_in_map: Pose) -> Pose:
    """Send the base to ``goal_in_map`` as the robot's navigation action (MoveBase or
    NavigateToPose, by its fact); return the base pose reached. Check the path first."""
    stamped = {"header": {"frame_id": client.fixed_frame}, "pose": pose_to_ros(goal_in_map)}
    kind = client.config.action("navigation").action_type
    # Nav2 names the goal's pose "pose" and runs its default behaviour tree for ""
    goal = {"pose": stamped} if kind == "nav2_msgs/NavigateToPose" else {"target_pose": stamped}
    client.run("navigation", goal, lambda text: NavigationGoalNotReached(text, target=goal_in_map))
    return client.base_pose()


class TorsoPM(RosProcessModule):
    """The torso over ``FollowJointTrajectory``: ``move_torso(Value)``."""

    name = "ros_torso"
    resource = "torso"

    def move_torso(self, value: float) -> float:
        """Send the torso joint's trajectory; return the value reached."""
        joint = self.client.desc.torso_joint
        if joint is None:
            raise RosCommandError(f"{self.client.name} has no torso joint; it cannot move one")
        goal = float(value)
        try:
            self.client.move_joints(
                "torso", {joint: goal}, lambda text: TorsoGoalNotReached(text, goal=goal)
            )
        except ManipulationPathBlocked as blocked:  # the world given to ros_robot blocks it
            raise TorsoPathBlocked(
                f"{self.client.name}'s torso cannot move to {goal}: {blocked}; nothing was sent",
                goal=goal,
                colliding_pairs=blocked.colliding_pairs,
                path_fraction=blocked.path_fraction,
            ) from blocked
        return self.client.joint_states()[joint]


class PtuPM(RosProcessModule):
    """The head: ``move_head(pose | frame | direction, X)`` over PointHead or pan/tilt joints;
    ``move_head(joints, C)``: the head's joints to ``C`` by a timed trajectory."""

    name = "ros_ptu"
    resource = "ptu"

    def _target(self, mode: str, goal: Value) -> tuple[float, float, float]:
        client = self.client
        if mode == "pose":
            return client.in_map(goal).position
        if mode == "frame":
            return client.frame_pose(str(goal)).position
        if mode == "direction":
            vector = goal.position if isinstance(goal, PoseStamped) else goal
            d = np.asarray(vector, float)
            if d.shape != (3,) or np.linalg.norm(d) < 1e-9:
                raise RosCommandError(
                    f"looking direction must be a non-zero 3-D vector, got {vector}"
                )
            base = client.base_pose().matrix()[:3, :3]
            camera = np.asarray(client.frame_pose(client.desc.cameras[0].frame).position)
            far = camera + DIRECTION_REACH * (base @ (d / np.linalg.norm(d)))
            return (float(far[0]), float(far[1]), float(far[2]))
        raise RosCommandError(f"move_head mode {mode!r} is none of pose, frame, direction")

    def move_head(self, mode: str, goal: Value) -> dict[str, float]:
        """Point the camera at a pose, a frame or along a direction; return pan and tilt.
        ``joints``: turn the head's joints to ``goal``; return their values reached."""
        client = self.client
        if mode == "joints":
            return self._turn_joints(goal)
        target = self._target(mode, goal)
        failure = lambda text: PtuGoalNotReached(text, target=target)  # noqa: E731
        interface = client.config.action("head")
        if interface.action_type.endswith("/PointHead"):  # control_msgs or the PR2's own
            x, y, z = target
            camera = client.desc.cameras[0].frame
            point_head = {
                "target": {
                    "header": {"frame_id": client.fixed_frame},
                    "point": {"x": x, "y": y, "z": z},
                },
                "pointing_axis": POINTING_AXIS,
                "pointing_frame": camera,
            }
            client.run("head", point_head, failure)
        else:  # a pan/tilt trajectory controller: the aim's timed trajectory, checked
            joints = client.actuated_joint_states()
            angles = pan_tilt_towards(client.desc, joints, client.base_pose(), target)
            try:
                client.move_joints("head", angles, failure)
            except ManipulationPathBlocked as blocked:  # the world given to ros_robot
                raise PtuPathBlocked(
                    f"{client.name} cannot turn its head to look at {target}: {blocked}; "
                    "nothing was sent",
                    target=target,
                    colliding_pairs=blocked.colliding_pairs,
                    path_fraction=blocked.path_fraction,
                ) from blocked
        pt = client.desc.pan_tilt
        joints = client.joint_states()
        return {j: joints[j] for j in ((pt.pan_joint, pt.tilt_joint) if pt else ())}

    def _turn_joints(self, configuration: object) -> dict[str, float]:
        """Send the head's joints to ``configuration`` (the neck's parking configuration)."""
        client = self.client
        values = joint_values(configuration)
        allowed = head_joints(client.desc)
        unknown = sorted(set(values) - allowed)
        if unknown:
            raise RosCommandError(
                f"joints {unknown} do not turn {client.name}'s head; give the head's joints "
                f"{sorted(allowed)}"
            )
        failure = lambda text: PtuGoalNotReached(text)  # noqa: E731
        try:
            client.move_joints("head", values, failure)
        except ManipulationPathBlocked as blocked:  # the world given to ros_robot
            raise PtuPathBlocked(
                f"{client.name} cannot turn its head to {values}: {blocked}; nothing was sent",
                colliding_pairs=blocked.colliding_pairs,
                path_fraction=blocked.path_fraction,
            ) from blocked
        joints = client.joint_states()
        return {j: joints[j] for j in values}


class PerceptionPM(RosProcessModule):
    """The camera over ``robocram_msgs/DetectObjects``: ``detect(ObjectDesig)``."""

    name = "ros_perception"
    resource = "perception"

    def inspect(self, designator: object) -> ObjectDesignator | list[ObjectDesignator]:
        """Inspect one object: our perception action reports all it sees when detecting."""
        return self.detect(designator)

    def detect(self, designator: object) -> ObjectDesignator | list[ObjectDesignator]:
        """Ask the perception server for the objects fitting ``designator``."""
        if not isinstance(designator, ObjectDesignator):
            raise RosUsageError(
                f"detecting needs an object designator (an.object(type=...)), got {designator!r}"
            )
        goal = {
            "object_type": str(designator.get("type") or ""),
            "object_name": str(designator.get("name") or ""),
        }
        notfound = lambda text: PerceptionObjectNotFound(text, object_designator=designator)  # noqa: E731
        outcome = self.client.run("perception", goal, notfound)
        objects = outcome.result.get("objects", [])
        if not objects:
            raise notfound(f"{self.client.name} sees no object fitting {designator.description}")
        seen = [
            PerceivedObject(str(o["name"]), str(o["type"]), pose_stamped_from_ros(o["pose"]))
            for o in objects
        ]
        if designator.quantifier is Quantifier.ALL:
            return [ObjectDesignator(type=s.type, name=s.name, pose=s.pose, data=s) for s in seen]
        first = seen[0]
        return designator.make_effective(first, type=first.type, name=first.name, pose=first.pose)


class GripperPM(RosProcessModule):
    """The grippers over ``GripperCommand``: ``move_gripper_joint(Arm, Action, Effort)``.

    Positions are the description's gripper joint values, turned into the controller's
    command and back by ``gripper_goal.py``. A gripper controller takes a position and
    stops where the fingers stall (on an object), so no trajectory is sent: the
    controller times the fingers itself.
    """

    name = "ros_grippers"
    resource = "grippers"

    def move_gripper_joint(self, gripper: str, action: object, effort: object) -> float:
        """Open, close or grip with ``gripper``'s hand, or move it to a position [rad | m];
        return the description's gripper joint value reached."""
        return move_gripper(self.client, gripper, action, effort)

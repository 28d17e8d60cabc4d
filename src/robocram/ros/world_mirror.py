"""The plan side's copy of the robot's world, kept as the robot side reports it over ROS.

``ros_robot(world=...)`` plans in a projection world of the robot's environment. Location
designators, grasps and motion checks read that world, so it must show what the robot
side sees: the robot's joints and base pose, the joints of articulated environments
(a kitchen's drawers and doors, on ``/<environment>/joint_states`` as iai_kitchen
publishes them, or the topic of a ``ros_topic(Robot, joint_states(Env), Topic)`` fact)
and the poses of the objects tf knows by name. What the robot holds cannot be read from
tf: when a gripper reports holding, the object between its fingers in the mirror is
attached to the hand (it then moves with the hand, as in projection), and opening lets
it go again.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from robocram.robots import LoadedDescription
from robocram.tf import Pose
from robocram.world import RobotObject, World

HOLD_REACH = 0.10  # [m] a held object's centre is at most this far from the tool frame


def environment_topics(world: World, configured: Mapping[str, str]) -> dict[str, str]:
    """``environment: joint-state topic`` of every articulated object in ``world`` that
    is not a robot: the configured topic, else ``/<name>/joint_states``."""
    return {
        obj.name: configured.get(obj.name, f"/{obj.name}/joint_states")
        for obj in world.objects()
        if not isinstance(obj, RobotObject) and world.joint_states(obj)
    }


class WorldMirror:
    """A world put into the state the robot side reports (call :meth:`sync`)."""

    def __init__(self, world: World, desc: LoadedDescription, topics: Mapping[str, str]) -> None:
        """``topics``: ``environment: joint-state topic`` (see :func:`environment_topics`)."""
        self.world = world
        self.desc = desc
        self.topics = dict(topics)

    def movable_objects(self) -> list[str]:
        """The objects whose pose is read from tf: not robots, not static, not held."""
        world = self.world
        return [
            obj.name
            for obj in world.objects()
            if not isinstance(obj, RobotObject)
            and not obj.is_static
            and world.bodies.attached_to(obj) is None
        ]

    def sync(
        self,
        joints: Mapping[str, float],
        base_in_map: Pose,
        environment_joints: Mapping[str, Mapping[str, float]],
        object_poses: Mapping[str, Pose],
    ) -> None:
        """Put robot, environments and objects where the robot side says they are.

        ``environment_joints`` are by topic (unheard topics are empty: left as they are);
        ``object_poses`` [map] by object name (objects missing keep their pose).
        """
        world, name, model = self.world, self.desc.name, self.desc.model
        known = world.joint_states(name)
        world.set_joint_states(
            name,
            {j: v for j, v in joints.items() if j in known and model.joints[j].mimic is None},
        )
        world.set_pose(name, base_in_map)
        for environment, topic in self.topics.items():
            heard = environment_joints.get(topic, {})
            have = world.joint_states(environment)
            world.set_joint_states(environment, {j: v for j, v in heard.items() if j in have})
        held = set(world.bodies.attachments(name))
        for obj, pose in object_poses.items():
            if obj in world and obj not in held:
                world.set_pose(obj, pose)

    def hold(self, arm: str) -> str | None:
        """Attach the object between ``arm``'s fingers to its hand; return its name (None
        if no object of the mirror is within :data:`HOLD_REACH` of the tool frame)."""
        spec = self.desc.arms[arm]
        already = self._held_by(arm)
        if already:
            return already[0]
        tool = np.asarray(self.world.link_pose(self.desc.name, spec.tool_frame).position)
        distances = {obj: self._distance(obj, tool) for obj in self.movable_objects()}
        near = {obj: d for obj, d in distances.items() if d <= HOLD_REACH}
        if not near:
            return None
        held = min(near, key=near.__getitem__)
        self.world.attach(held, self.desc.name, spec.end_effector_link)
        return held

    def release(self, arm: str) -> list[str]:
        """Let go of what ``arm``'s hand holds in the mirror; return the objects' names."""
        held = self._held_by(arm)
        for obj in held:
            self.world.detach(obj)
        return held

    def _held_by(self, arm: str) -> list[str]:
        spec = self.desc.arms[arm]
        links = {spec.end_effector_link, spec.tool_frame, *spec.gripper_links, *spec.hand_links}
        return [
            o for o, link in self.world.bodies.attachments(self.desc.name).items() if link in links
        ]

    def _distance(self, obj: str, point: np.ndarray) -> float:
        low, high = self.world.aabb(obj)
        centre = (np.asarray(low) + np.asarray(high)) / 2.0
        return float(np.linalg.norm(centre - point))

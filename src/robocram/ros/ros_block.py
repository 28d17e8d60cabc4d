"""``with ros_robot("pr2", master_uri=...):`` — CRAM's ``on-real-pr2`` for any robot behind ROS.

The block is a top level whose PERFORM goes to the robot's ROS process modules. Entering
starts our ROS node (a child process) and binds a transform tree answered by tf2; leaving
cancels what runs and stops the node, so no thread, node or subscriber is left. The
knowledge base holds the robot's description facts, the common motion groundings, its
ROS facts (``robots/<robot>.pl`` unless ``ros_facts`` is given) and the matching facts.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from robocram.costmaps import CostmapLocations
from robocram.designators import install_common_motions
from robocram.execution import Environment, TaskTree, TopLevel, matching_facts, top_level
from robocram.grasping import install_grasp_predicates
from robocram.logic import KnowledgeBase
from robocram.motion import MotionSettings
from robocram.robots import RobotDescription, install_description, load_description
from robocram.ros.arm_module import ArmPM
from robocram.ros.availability import require_ros_extra
from robocram.ros.errors import RosConfigError
from robocram.ros.process_modules import (
    GripperPM,
    NavigationPM,
    PerceptionPM,
    PtuPM,
    RosProcessModule,
    TorsoPM,
)
from robocram.ros.ros2_environment import require_ros2
from robocram.ros.ros_config import install_ros_facts, read_ros_config
from robocram.ros.ros_robot_client import DEFAULT_MASTER_TIMEOUT, RosRobotClient
from robocram.ros.ros_transform_tree import RosTransformTree
from robocram.tf import using_transform_tree
from robocram.world import World

# motion table resource -> the ros_action/4 resources that serve it
MODULES: dict[str, tuple[type[RosProcessModule], str]] = {
    "navigation": (NavigationPM, "navigation"),
    "torso": (TorsoPM, "torso"),
    "ptu": (PtuPM, "head"),
    "perception": (PerceptionPM, "perception"),
    "grippers": (GripperPM, "gripper("),
    "arms": (ArmPM, "arm("),
}


class RosEnvironment(Environment):
    """An environment whose process modules talk to one robot through our ROS node."""

    def __init__(
        self,
        client: RosRobotClient,
        kb: KnowledgeBase,
        locations: CostmapLocations | None = None,
    ) -> None:
        served = [
            resource
            for resource, (_, prefix) in MODULES.items()
            if any(key.startswith(prefix) for key in client.config.actions)
        ]
        super().__init__(
            f"ros_{client.name}",
            process_modules=[MODULES[resource][0](client) for resource in served],
            facts=matching_facts("ros", served),
            kb=kb,
            location_resolver=locations.resolver() if locations is not None else None,
        )
        self.client = client

    @contextmanager
    def running(self) -> Iterator[Environment]:
        """Start our ROS node, then the environment; stop both on leaving.

        Raises:
            RosCancelIgnored: on leaving without another error, if a server did not
                confirm a cancel of a stopped task (the robot may still be moving).
        """
        self.client.connect()
        try:
            with super().running() as environment:
                yield environment
            self.client.raise_unconfirmed_cancel()
        finally:
            self.client.disconnect()


def ros_environment(
    robot: str | RobotDescription = "pr2",
    master_uri: str | None = None,
    ros_facts: str | None = None,
    node_name: str = "robocram",
    world: World | None = None,
    motion: MotionSettings | None = None,
    master_timeout: float = DEFAULT_MASTER_TIMEOUT,
    locations: CostmapLocations | None = None,
    ros: int = 1,
    domain_id: int | None = None,
) -> RosEnvironment:
    """The environment of ``robot`` behind ROS 1's master at ``master_uri`` or on ROS 2.

    Args:
        master_uri: ROS 1's master; default ``$ROS_MASTER_URI``.
        ros_facts: Prolog text with the robot's ``ros_action/4`` ... facts (docs/ros.md);
            default: the packaged ones of a built-in robot.
        world: a projection world of the robot's environment with the robot in it (e.g.
            ``tabletop_scene("pr2").world``); before each motion it is put into the robot's
            state read from ROS (``world_mirror.py``), arm, torso and base motions are
            checked and planned in it, its knowledge base is the plans' (the scene's
            facts: places, containers, link poses) and location designators resolve by
            costmaps on it. None: nothing in the environment is checked (straight joint
            moves) and location designators are poses only.
        motion: how arm paths are planned in the world (seed, budget); default settings.
        master_timeout: [s] entering waits this long for the master to answer, then
            raises ``RosMasterUnreachable``.
        locations: resolves location designators (default with a world: costmaps on
            it, seed 0, as in projection).
        ros: 1 (rospy, a master) or 2 (rclpy, ros2_control and Nav2; docs/ros2.md).
        domain_id: ROS 2's ``ROS_DOMAIN_ID`` (0..101); default ``$ROS_DOMAIN_ID``, else 0.
    """
    uri, domain = _connection(ros, master_uri, domain_id)
    desc = load_description(robot)
    kb = world.kb if world is not None else KnowledgeBase()  # the scene's facts for plans
    install_description(kb, desc)
    install_common_motions(kb)
    install_ros_facts(kb, desc.name, ros_facts, ros=ros)
    if world is None:
        install_grasp_predicates(kb, description=desc)  # by the perceived type and pose
    else:
        install_grasp_predicates(kb, world)  # on the world's objects, as in projection
        locations = locations or CostmapLocations(world)
    client = RosRobotClient(
        desc,
        read_ros_config(kb, desc),
        uri,
        node_name,
        world=world,
        motion=motion,
        master_timeout=master_timeout,
        ros=ros,
        domain_id=domain,
    )
    return RosEnvironment(client, kb, locations)


def _connection(ros: int, master_uri: str | None, domain_id: int | None) -> tuple[str, int]:
    """The master URI (ROS 1) or domain (ROS 2), checked; the ROS asked for must be set up."""
    if ros == 1:
        require_ros_extra()
        uri = master_uri or os.environ.get("ROS_MASTER_URI")
        if not uri:
            raise RosConfigError("no ROS master: pass master_uri= or set ROS_MASTER_URI")
        return uri, 0
    if ros == 2:
        require_ros2()
        domain = domain_id if domain_id is not None else int(os.environ.get("ROS_DOMAIN_ID", 0))
        if not 0 <= domain <= 101:
            raise RosConfigError(f"ROS_DOMAIN_ID must be in 0..101, got {domain}")
        return "", domain
    raise RosConfigError(f"ros={ros!r}: robocram speaks ROS 1 (ros=1) and ROS 2 (ros=2)")


@dataclass(frozen=True)
class RosRun:
    """What a ``ros_robot`` block yields: its environment, top level and frames."""

    environment: RosEnvironment
    top_level: TopLevel
    transforms: RosTransformTree

    @property
    def tree(self) -> TaskTree:
        """The task tree of the block (complete once the block has ended)."""
        return self.top_level.tree


@contextmanager
def ros_robot(
    robot: str | RobotDescription = "pr2",
    master_uri: str | None = None,
    ros_facts: str | None = None,
    name: str = "ros-robot",
    world: World | None = None,
    motion: MotionSettings | None = None,
    master_timeout: float = DEFAULT_MASTER_TIMEOUT,
    locations: CostmapLocations | None = None,
    ros: int = 1,
    domain_id: int | None = None,
) -> Iterator[RosRun]:
    """Run the block as a top level on ``robot`` behind ROS (see :func:`ros_environment`;
    ``world`` is the environment motions are checked and planned in; ``ros=2`` speaks
    ROS 2 on ``domain_id``)."""
    environment = ros_environment(
        robot,
        master_uri,
        ros_facts,
        world=world,
        motion=motion,
        master_timeout=master_timeout,
        locations=locations,
        ros=ros,
        domain_id=domain_id,
    )
    transforms = RosTransformTree(lambda: environment.client.transport)
    runner = top_level(name=name)
    with environment, using_transform_tree(transforms), runner:
        yield RosRun(environment, runner, transforms)

"""What a pick from a stand needs: the grasps the pick plan will try, and collision checks.

A stand for picking an object up is only worth taking if the pick will work from there.
The pick plan (``plans.pick_object``) takes the grasp model's candidates
(:mod:`robocram.grasping`) best first, moves the tool to the pre-grasp avoiding every
collision, then to the grasp where the hand may touch. The reachable validator checks the
same: these targets, and :func:`collides` with the pick's collision modes.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from robocram.grasping import GraspingError, candidates_at, grasp_names, object_shape
from robocram.tf import Pose
from robocram.world import RobotObject, World, WorldObject
from robocram.world.link_contacts import link_contacts


@dataclass(frozen=True)
class PickTarget:
    """One grasp the pick will try: its name and the tool poses in the robot's base frame."""

    grasp: str
    grasp_in_base: Pose
    pre_grasp_in_base: Pose


def pick_targets(
    world: World, robot: RobotObject, obj: WorldObject, arm: str, base: Pose
) -> list[PickTarget]:
    """The grasps of ``obj`` by ``arm`` for the robot standing at ``base``, best first.

    Empty when the arm's hand fits no grasp (or has no gripper): it cannot pick the object.
    """
    try:
        shape = object_shape(world, obj)
        names = grasp_names(world.kb, obj.type)
        found = candidates_at(shape, world.pose(obj), robot.description, arm, base, names)
    except GraspingError:
        return []
    to_base = base.inverse()
    return [PickTarget(c.grasp.name, to_base * c.tool, to_base * c.pre_grasp) for c in found]


def collides(
    world: World,
    robot: RobotObject,
    arm: str,
    stand: Pose,
    joints: Mapping[str, float],
    touching: WorldObject | None = None,
) -> bool:
    """Whether the robot at ``stand`` with ``joints`` touches anything but the floor.

    With ``touching`` (the object grasped) its hand and gripper links may touch, as the
    pick's ``allow_hand`` mode lets them. Joints and pose are restored afterwards.
    """
    spec = robot.description.arms[arm]
    allowed: set[str] = set()
    if touching is not None:
        allowed = {*spec.hand_links, *spec.gripper_links, spec.end_effector_link, spec.tool_frame}
    model = robot.description.model
    assert model is not None
    before = {j: v for j, v in world.joint_states(robot).items() if model.joints[j].mimic is None}
    pose = world.pose(robot)
    world.set_pose(robot, stand)
    world.set_joint_states(robot, dict(joints))
    try:
        floors = world.objects(type="floor")
        hits = link_contacts(world, robot, ignore=floors, distance=0.0)
        return any(link not in allowed for link, _ in hits)
    finally:
        world.set_joint_states(robot, before)
        world.set_pose(robot, pose)

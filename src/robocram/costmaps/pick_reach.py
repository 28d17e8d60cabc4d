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
from typing import Any

from robocram.grasping import GraspingError, candidates_at, grasp_names, object_shape
from robocram.robots import RobotModel
from robocram.tf import Pose
from robocram.world import RobotObject, World, WorldObject
from robocram.world.link_contacts import link_contacts

HAND_DEPTH = 0.005  # [m] the deepest a grasping hand may go into the object: the pick's
# bound (``motion.hand_contact.HAND_CONTACT_DEPTH``), so a stand the validator takes is
# one the pick's IK can take (the TIAGo's thumb 6.5 mm in the mug passed here, then every
# IK solution of the pick was refused)


@dataclass(frozen=True)
class PickTarget:
    """One grasp the pick will try: its name and the tool poses in the robot's base frame."""

    grasp: str
    grasp_in_base: Pose
    pre_grasp_in_base: Pose


def pick_targets(
    world: World,
    robot: RobotObject,
    obj: WorldObject,
    arm: str,
    base: Pose,
    memo: dict[Any, Any] | None = None,
) -> list[PickTarget]:
    """The grasps of ``obj`` by ``arm`` for the robot standing at ``base``, best first.

    Empty when the arm's hand fits no grasp (or has no gripper): it cannot pick the object.
    ``memo`` keeps the object's shape and grasp names between calls for the object where
    it is now (one location resolution: the object stays put).
    """
    key = ("pick_shape", obj.name, world.pose(obj))
    memo = {} if memo is None else memo
    try:
        if key not in memo:
            memo[key] = (object_shape(world, obj), grasp_names(world.kb, obj.type))
        shape, names = memo[key]
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
    allow_hand: bool = False,
) -> bool:
    """Whether a link the motion moves touches anything but the floor
    (:func:`touched_objects` is not empty)."""
    return bool(touched_objects(world, robot, arm, stand, joints, allow_hand))


def touched_objects(
    world: World,
    robot: RobotObject,
    arm: str,
    stand: Pose,
    joints: Mapping[str, float],
    allow_hand: bool = False,
    touching: str | None = None,
) -> list[str]:
    """The objects a link the motion moves touches (the floor left out), each once.

    The robot stands at ``stand`` and takes ``joints``; the links checked are those the
    changed joints move, all of them if the robot stands elsewhere than now (the robot
    standing there, parked, is the ``robot_collision_free`` validator's check). With
    ``allow_hand`` the arm's hand and gripper links may touch (the object grasped, the
    surface a held object is put on), as the plans' ``allow_hand`` mode lets them; on
    ``touching`` (the object picked) at most :data:`HAND_DEPTH` deep, as the pick's bound.
    Joints and pose are restored afterwards.
    """
    spec = robot.description.arms[arm]
    allowed: set[str] = set()
    if allow_hand:
        allowed = {*spec.hand_links, *spec.gripper_links, spec.end_effector_link, spec.tool_frame}
    model = robot.description.model
    assert model is not None
    before = {j: v for j, v in world.joint_states(robot).items() if model.joints[j].mimic is None}
    pose = world.pose(robot)
    changed = [j for j, v in joints.items() if abs(before.get(j, v) - v) > 1e-9]
    here = stand.distance_to(pose) < 1e-6 and stand.angle_to(pose) < 1e-6
    moved = _moved_links(model, changed, robot) if here else None
    if not here:  # standing there already (the validator placed it): no move to undo
        world.set_pose(robot, stand)
    world.set_joint_states(robot, dict(joints))
    try:
        floors = world.objects(type="floor")
        hits = link_contacts(world, robot, links=moved, ignore=floors, distance=0.0)
        return list(dict.fromkeys(
            other for link, other in hits
            if link not in allowed or _too_deep(world, robot, link, other, touching)
        ))  # fmt: skip
    finally:
        world.set_joint_states(robot, before)
        if not here:
            world.set_pose(robot, pose)


def _too_deep(
    world: World, robot: RobotObject, link: str, other: str, touching: str | None
) -> bool:
    """Whether hand ``link`` is in ``other``, the grasp's object ``touching``, deeper than
    :data:`HAND_DEPTH` (False for anything else: the hand may touch it)."""
    name, _, other_link = other.partition("/")
    if touching is None or touching not in (other, name):
        return False
    points = world.contacts.contact_points(robot, name, link, other_link or None, 0.0)
    return max((-p.distance for p in points), default=0.0) > HAND_DEPTH


class _Children:
    """The child links of each link of one model (a model never changes)."""

    def __init__(self, model: RobotModel) -> None:
        self.below: dict[str, list[str]] = {}
        for joint in model.joints.values():
            self.below.setdefault(joint.parent, []).append(joint.child)


def _moved_links(model: RobotModel, joints: list[str], robot: RobotObject) -> list[str]:
    """The links below ``joints`` (their children and everything further out) in the body."""
    below = model.derived(_Children).below
    found = [model.joints[j].child for j in joints if j in model.joints]
    for link in found:
        found.extend(below.get(link, ()))
    return [link for link in dict.fromkeys(found) if link in robot.link_index]

"""CRAM's collision modes for arm motions, as IK collision checks on the projected world.

``avoid_all``: no link of the robot may touch anything (the floor and objects the robot
holds excepted). ``allow_hand``: the moving arm's hand and gripper links may touch (for
grasping). ``allow_all``: no check. A candidate configuration is tried on the world and the
joints are put back before the check returns, so IK never leaves the robot moved.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

from robocram.kinematics import split_base_motion
from robocram.motion.collision_modes import COLLISION_MODES, hand_links
from robocram.projection.errors import ProjectionError
from robocram.projection.navigation import base_moved_by
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import RobotModel

CONTACT_DISTANCE = 0.0  # [m] closer than this is a collision (touching counts)


def collision_check(
    robot: ProjectedRobot, arm: str, mode: str
) -> Callable[[Mapping[str, float]], list[tuple[str, str]]] | None:
    """An IK ``collision_check`` for ``mode`` (None for ``allow_all``).

    It returns the colliding ``(robot link, object)`` pairs, so a failure can name them.
    """
    mode = mode.replace("-", "_")
    if mode not in COLLISION_MODES:
        raise ProjectionError(
            f"unknown collision mode {mode!r} for the {arm} arm; use one of {COLLISION_MODES}"
        )
    if mode == "allow_all":
        return None
    allowed = allowed_links(robot, arm, mode)

    own = self_pairs(robot, arm)

    def collides(candidate: Mapping[str, float]) -> list[tuple[str, str]]:
        joints, motion = split_base_motion(candidate)  # IK that moves the base too
        with base_moved_by(robot, motion):
            return colliding_pairs(robot, joints, allowed, own)

    return collides


def allowed_links(robot: ProjectedRobot, arm: str, mode: str) -> set[str]:
    """The links that may touch things in ``mode``: the hand's for ``allow_hand``."""
    mode = mode.replace("-", "_")
    if mode != "allow_hand":
        return set()
    return hand_links(robot.arm(arm))


def self_pairs(robot: ProjectedRobot, arm: str) -> list[tuple[str, str]]:
    """Pairs of ``arm``'s links and the robot's other links that may collide: both with a
    collision shape (of 1,239 pairs of a PR2 arm, 216), apart now, and not joined by one
    joint (the shoulder sits on the torso)."""
    world = robot.world
    body = world.object(robot.name)
    shaped = body.colliders
    links = tuple(n for n in world.link_names(body) if body.link_index[n] in shaped)
    first = robot.arm(arm).joints[0]
    pairs = robot.description.model.derived(_ArmPairs).of(first, links)
    touching = set(world.self_contacts(robot.name, pairs))
    return [pair for pair in pairs if pair not in touching]


@dataclass
class _ArmPairs:
    """Per arm: its links paired with the robot's others, shoulder joint excepted. They
    follow from the model alone, so they are kept with it (``RobotModel.derived``): IK
    asks for them at every query."""

    model: RobotModel
    _found: dict[tuple[str, tuple[str, ...]], list[tuple[str, str]]] = field(default_factory=dict)

    def of(self, first: str, links: tuple[str, ...]) -> list[tuple[str, str]]:
        """The pairs for the arm whose first joint is ``first``, among ``links``."""
        key = (first, links)
        found = self._found.get(key)
        if found is None:
            joint = self.model.joints[first]
            below = _subtree(self.model, joint.child)
            others = [link for link in links if link not in below]
            mine = [link for link in links if link in below]
            found = self._found.setdefault(key, [
                (a, b) for a in mine for b in others
                if b != joint.parent and a != joint.child
            ])  # fmt: skip
        return found


def _subtree(model: RobotModel, link: str) -> set[str]:
    children: dict[str, list[str]] = {}
    for joint in model.joints.values():
        children.setdefault(joint.parent, []).append(joint.child)
    found, todo = set(), [link]
    while todo:
        item = todo.pop()
        if item not in found:
            found.add(item)
            todo.extend(children.get(item, ()))
    return found


def colliding_pairs(
    robot: ProjectedRobot,
    joints: Mapping[str, float],
    allowed_links: set[str],
    own: Sequence[tuple[str, str]] = (),
) -> list[tuple[str, str]]:
    """``(robot link, object)`` pairs in contact at ``joints``, ``allowed_links`` excepted.

    The object is named by itself, or as ``object/link`` when it has several links.
    """
    world = robot.world
    before = _to_restore(robot, joints)
    world.set_joint_states(robot.name, dict(joints))
    try:
        held = set(world.attachments(robot.name))
        ignore = [o for o in world.objects() if o.name in held or o.type == "floor"]
        hits: dict[tuple[str, str], None] = {}
        for link, obj, other_link in world.link_pairs_in_contact(
            robot.name, ignore, CONTACT_DISTANCE
        ):
            if link not in allowed_links:
                several = len(obj.link_index) > 1
                hits[(link, f"{obj.name}/{other_link}" if several else obj.name)] = None
        for pair in world.self_contacts(robot.name, own):
            hits[pair] = None
        return list(hits)
    finally:
        world.set_joint_states(robot.name, before)


def _to_restore(robot: ProjectedRobot, joints: Mapping[str, float]) -> dict[str, float]:
    """The joint values that put the robot back after it is set to ``joints``: those the
    check changes, and every other one simulation does not hold where it is (putting it
    back holds it there, as putting back every joint did). Mimic followers come back with
    their masters."""
    world = robot.world
    model = robot.description.model
    held = world.held_joints(robot.name)
    mimics = (model.joints[j].mimic for j in joints)
    masters = {mimic.joint for mimic in mimics if mimic is not None}
    return {
        joint: value
        for joint, value in world.joint_states(robot.name).items()
        if model.joints[joint].mimic is None
        and (joint in joints or joint in masters or held.get(joint) != value)
    }

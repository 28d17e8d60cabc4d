"""The pairs of a held thing and the robot's own links that a motion moves together.

The world clearances measure what a hand holds against everything but the robot; the
robot's own pairs are its links. Neither sees a held thing swing into the robot itself:
Boxy's 16 cm spoon went 27 mm into its base on the way to a stir's start. Here a held
thing is one more member of the self walk
(:class:`~robocram.motion.self_path_check.SelfPathCheck`): its convex parts (the ones its
world clearances use) ride on its carrier's joint, and it is paired with every link of
the robot that the planned joints move relative to the carrier, but the hand holding it
(its fingers close on it and open off it: the grip's contacts are the gripper's to bound).
"""

from __future__ import annotations

from collections.abc import Hashable, Sequence

import numpy as np

from robocram.motion.clearance_setup import SetupCache
from robocram.motion.coal_self_distances import SelfParts
from robocram.motion.configuration_checker import LinkPair
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.robot_geometry import Part, RobotGeometry
from robocram.motion.self_collision import active_joints, follower_fold
from robocram.motion.travel_bound import TravelBound
from robocram.world import RobotHandle

HeldPairs = tuple[tuple[LinkPair, ...], FloatArray, SelfParts]  # pairs, levers, parts


def held_pairs(robot: RobotHandle, joints: Sequence[str]) -> HeldPairs | None:
    """The (held thing, robot link) pairs a motion of ``joints`` moves relative to each
    other, with their levers (pairs, joints) [m per unit] and parts; None when the robot
    holds nothing with parts, or the joints move nothing it holds."""
    world = robot.world
    held = world.bodies.attachments(robot.name)
    if not held:
        return None
    model = robot.description.model
    geometry = model.derived(RobotGeometry.of)
    body = world.object(robot.name)
    joints = tuple(joints)
    active = sorted(active_joints(model, joints))
    bound = TravelBound.of(robot, active, held=True)
    fold = follower_fold(model, active, joints)
    names = body.index_names()
    members: dict[int, list[str]] = {}  # per PyBullet link with parts: the links folded in
    for link in geometry.parts:
        index = body.link_index.get(link)
        if index is not None and index in body.colliders:
            members.setdefault(index, []).append(link)
    zero = np.zeros(len(active))
    lever = {  # per PyBullet link: the most any of its links moves (folded links differ)
        index: np.max([bound.link_lever.get(link, zero) for link in links], axis=0)
        for index, links in members.items()
    }
    cache = world.derived(SetupCache)
    pieces: dict[Hashable, Sequence[Part]] = {}
    group_of: dict[str, Hashable] = {}
    pairs: list[LinkPair] = []
    rows: list[FloatArray] = []
    for name, carrier in sorted(held.items()):
        parts = cache.held_parts(geometry, body, name, carrier)
        if not parts:
            continue
        riding = bound.link_lever.get(carrier, zero)
        grip = {body.link_index.get(link) for link in _holding_hand(robot, carrier)}
        for index, moved in sorted(lever.items()):
            if index in grip:
                continue
            relative = np.where((riding > 0.0) & (moved > 0.0), 0.0, riding + moved) @ fold
            if not relative.any():
                continue
            link = names[index]
            pieces[("held", name)] = parts
            pieces[index] = [p for each in members[index] for p in geometry.parts[each]]
            group_of[name], group_of[link] = ("held", name), index
            pairs.append((name, link))
            rows.append(relative)
    if not pairs:
        return None
    levers = np.array(rows, dtype=float).reshape(len(pairs), len(joints))
    return tuple(pairs), levers, SelfParts.grouped(pieces, group_of, pairs)


def _holding_hand(robot: RobotHandle, carrier: str) -> set[str]:
    """The links of the hand that holds a thing on ``carrier``: the grip's own contacts
    (fingers closing on it, opening off it) are the gripper's to bound, not the walk's."""
    links = {carrier}
    for arm in robot.description.arms.values():
        hand = {*arm.hand_links, *arm.gripper_links, arm.tool_frame, arm.end_effector_link}
        if carrier in hand:
            links |= hand
    return links

"""Which robot link pairs a self-collision check looks at, MoveIt's way.

Two links are checked when some planned joint moves one relative to the other (else their
contact never changes) and the robot's
:class:`~robocram.motion.self_collision_matrix.SelfCollisionMatrix` checks them (not
adjacent: joined by one joint, links without geometry and fixed joints looked through;
not always in contact; not touching at rest or across one flexed joint). An arm is
checked against the torso, the base, the head, the other arm and its own hand.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence

import numpy as np

from robocram.motion.joint_trajectory import FloatArray
from robocram.robots import RobotModel


def active_joints(model: RobotModel, joints: Collection[str]) -> set[str]:
    """``joints`` and every mimic joint that follows one of them, transitively."""
    active = set(joints)
    changed = True
    while changed:
        changed = False
        for joint in model.joints.values():
            if joint.mimic is not None and joint.mimic.joint in active and joint.name not in active:
                active.add(joint.name)
                changed = True
    return active


def follower_fold(model: RobotModel, active: Sequence[str], joints: Sequence[str]) -> FloatArray:
    """(active, joints): each planned joint's column onto itself and, scaled by the size of
    their multiplier, the mimic followers in ``active`` that follow it (levers per active
    joint become levers per planned joint)."""
    column = {j: i for i, j in enumerate(active)}
    fold = np.zeros((len(active), len(joints)))
    for i, name in enumerate(joints):
        fold[column[name], i] = 1.0
    for name in active:
        mimic = model.joints[name].mimic
        if mimic is not None and mimic.joint in joints:
            fold[column[name], list(joints).index(mimic.joint)] = abs(mimic.multiplier)
    return fold


def moving_group(model: RobotModel, active: Collection[str]) -> dict[str, str]:
    """Per link, the nearest active joint above it ("" when none): links of one group never
    move relative to each other."""
    group: dict[str, str] = {}

    def find(link: str) -> str:
        if link not in group:
            joint = model.parent_joint(link)
            if joint is None:
                group[link] = ""
            elif joint.name in active:
                group[link] = joint.name
            else:
                group[link] = find(joint.parent)
        return group[link]

    for link in model.links:
        find(link)
    return group


def adjacent_pairs(model: RobotModel, with_geometry: Collection[str]) -> set[frozenset[str]]:
    """Pairs of links with geometry joined by one movable joint, or rigidly fixed together.

    Links without geometry and fixed joints are looked through: a wrist frame between two
    links makes them adjacent still.
    """
    rigid = _rigid_roots(model)
    body_links: dict[str, set[str]] = {}
    for link in with_geometry:
        body_links.setdefault(rigid[link], set()).add(link)
    neighbours: dict[str, set[str]] = {root: set() for root in set(rigid.values())}
    for joint in model.joints.values():
        if joint.movable:
            a, b = rigid[joint.parent], rigid[joint.child]
            neighbours[a].add(b)
            neighbours[b].add(a)
    for body in list(neighbours):  # bodies without geometry join their neighbours
        if body not in body_links:
            around = neighbours[body]
            for a in around:
                neighbours[a] |= around - {a}
    pairs: set[frozenset[str]] = set()
    for body, links in body_links.items():
        for other in neighbours[body] | {body}:
            for a in links:
                pairs.update(frozenset((a, b)) for b in body_links.get(other, ()) if a != b)
    return pairs


def _rigid_roots(model: RobotModel) -> dict[str, str]:
    """Per link, the top link of the group it is fixed to by fixed joints."""
    roots: dict[str, str] = {}

    def find(link: str) -> str:
        if link not in roots:
            joint = model.parent_joint(link)
            roots[link] = link if joint is None or joint.movable else find(joint.parent)
        return roots[link]

    for link in model.links:
        find(link)
    return roots

"""Which of a robot's links a motion moves, and which pairs of them it moves apart.

A link's group is the nearest joint above it that the motion moves (``""``: none; a base
motion moves the root, group ``"base"``). Links of one group keep their places relative
to each other during the motion; a pair of links in different groups moves relatively.
Mimic joints move with their masters.
"""

from __future__ import annotations

from collections.abc import Collection

from robocram.motion import BODY_JOINTS
from robocram.robots import RobotModel


def moving_groups(model: RobotModel, joints: Collection[str]) -> dict[str, str]:
    """Per link of ``model``: the nearest moved joint above it, ``"base"`` or ``""``."""
    active = set(joints)
    changed = True
    while changed:
        followers = {
            j.name for j in model.joints.values() if j.mimic is not None and j.mimic.joint in active
        }
        changed = not followers <= active
        active |= followers
    root = "base" if active & set(BODY_JOINTS) else ""
    group: dict[str, str] = {}

    def find(link: str) -> str:
        if link not in group:
            joint = model.parent_joint(link)
            if joint is None:
                group[link] = root
            elif joint.name in active:
                group[link] = joint.name
            else:
                group[link] = find(joint.parent)
        return group[link]

    for link in model.links:
        find(link)
    return group

"""The torso of a drafted robot: a vertical prismatic joint that carries arms or the head.

A ``<mimic>`` follower is never the torso (no one commands it: the HSR's head lift
follows its arm lift). Among the rest, the joint carrying the most hands wins.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.robots.draft.link_poses import axis_in_root, link_poses
from robocram.robots.draft.model_tree import ModelTree

VERTICAL = 0.9  # |z| of a unit axis in the root link above which it is vertical


@dataclass(frozen=True)
class Torso:
    """The torso joint and its link, and why; ``None`` fields for a robot without one."""

    joint: str | None
    link: str | None
    why: str
    doubt: str | None = None


def find_torso(tree: ModelTree, carried: list[str]) -> Torso:
    """The vertical prismatic joint above the most of ``carried`` (hand and camera links)."""
    model = tree.model
    poses = link_poses(model)
    vertical = [
        joint
        for joint in model.joints.values()
        if joint.type == "prismatic"
        and joint.mimic is None
        and abs(axis_in_root(model, joint.name, poses)[2]) > VERTICAL
    ]
    scored = [(sum(tree.below(j.child, link) for link in carried), j) for j in vertical]
    scored = [(n, j) for n, j in scored if n > 0]
    if not scored:
        return Torso(None, None, "no vertical prismatic joint carries an arm or the camera")
    best = max(n for n, _ in scored)
    chosen = [j for n, j in scored if n == best]
    joint = chosen[0]
    why = f"vertical prismatic joint carrying {best} of the arms and cameras"
    doubt = None
    if len(chosen) > 1:
        doubt = f"as likely: {', '.join(j.name for j in chosen[1:])}"
    return Torso(joint.name, joint.child, why, doubt)

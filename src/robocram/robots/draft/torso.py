"""The torso of a drafted robot: a vertical prismatic joint that raises the camera.

A joint is a torso only if moving it raises the camera, itself or through the joints that
``<mimic>`` it (the HSR's head lift follows its arm lift), or more than one arm (Boxy's).
A lift that carries one arm only (Stretch's ``joint_lift``: its camera stands on the fixed
mast) belongs to that arm: plans raise the torso to look, which would only put the arm
before the camera. A follower is never the torso (no one commands it). Among the rest, the
joint carrying the most hands and cameras wins.
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


def _raises(tree: ModelTree, joint: str, link: str) -> bool:
    """Whether moving ``joint`` moves ``link``: it hangs below it or below a follower."""
    movers = [joint, *tree.followers(joint)]
    return any(tree.below(tree.model.joints[name].child, link) for name in movers)


def find_torso(tree: ModelTree, hands: list[str], cameras: list[str]) -> Torso:
    """The vertical prismatic joint raising a camera and the most hand and camera links."""
    model = tree.model
    poses = link_poses(model)
    vertical = [
        joint
        for joint in model.joints.values()
        if joint.type == "prismatic"
        and joint.mimic is None
        and abs(axis_in_root(model, joint.name, poses)[2]) > VERTICAL
    ]
    raising = [
        j
        for j in vertical
        if any(_raises(tree, j.name, c) for c in cameras)
        or sum(_raises(tree, j.name, h) for h in hands) > 1
    ]
    scored = [(sum(tree.below(j.child, link) for link in hands + cameras), j) for j in raising]
    if not scored:
        lifts = [j.name for j in vertical if any(_raises(tree, j.name, h) for h in hands)]
        why = "no vertical prismatic joint raises the camera"
        lifted = f"; {', '.join(lifts)}: a lift of one arm, drafted in that arm" if lifts else ""
        return Torso(None, None, why + lifted)
    best = max(n for n, _ in scored)
    chosen = [j for n, j in scored if n == best]
    joint = chosen[0]
    why = f"vertical prismatic joint carrying {best} of the arms and cameras"
    doubt = None
    if len(chosen) > 1:
        doubt = f"as likely: {', '.join(j.name for j in chosen[1:])}"
    return Torso(joint.name, joint.child, why, doubt)

"""Which way a gripper joint opens: the limit at which its fingers stand farther apart.

robocram opens a gripper at its joints' upper limits unless the description says
otherwise; many grippers (Robotiq's, PAL's) close at the upper limit instead. The spread is
the mean distance of the links a joint moves from the hand's approach axis: of their frames,
or, where those stay put (a jaw turning about its own frame's origin), of the middles of
their collision shapes.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.robots.draft.hands import Hand
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.link_centre import link_centre
from robocram.tf import Pose

SPREAD_DIFFERENCE = 1e-3  # [m] less than this between the limits: the direction is unknown


def _spread(
    tree: ModelTree,
    hand: Hand,
    joint: str,
    value: float,
    approach: np.ndarray,
    centres: bool = False,
) -> float:
    poses = link_poses(tree.model, {joint: value})
    wrist = poses[hand.end_effector_link].inverse()
    moved = [tree.model.joints[joint].child, *tree.subtree_links(tree.model.joints[joint].child)]
    moved += [
        f for g in tree.followers(joint) for f in tree.subtree_links(tree.model.joints[g].child)
    ]
    moved += [tree.model.joints[g].child for g in tree.followers(joint)]
    distances = []
    for link in dict.fromkeys(moved):
        at = Pose(link_centre(tree.model.link(link))) if centres else Pose()
        point = np.asarray((wrist * poses[link] * at).position)
        distances.append(float(np.linalg.norm(point - (point @ approach) * approach)))
    return float(np.mean(distances)) if distances else 0.0


def opens_at_upper(tree: ModelTree, hand: Hand, joint: str, approach: np.ndarray) -> bool | None:
    """Whether ``joint``'s fingers stand wider at its upper limit; None if it cannot tell."""
    spec = tree.model.joints[joint]
    if spec.lower is None or spec.upper is None:
        return None
    if not (math.isfinite(spec.lower) and math.isfinite(spec.upper)):
        return None
    for centres in (False, True):
        low = _spread(tree, hand, joint, spec.lower, approach, centres)
        high = _spread(tree, hand, joint, spec.upper, approach, centres)
        if abs(high - low) >= SPREAD_DIFFERENCE:
            return high > low
    return None

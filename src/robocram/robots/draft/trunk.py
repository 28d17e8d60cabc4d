"""The trunk of a drafted robot: movable joints every arm and the camera hang below.

A humanoid's waist (TALOS's ``torso_1_joint`` and ``torso_2_joint``) turns both arms and
the head. Left in the chains it would make each arm two joints longer, shared with the
other arm, and the head a four-joint neck arm instead of a pan-tilt unit. The draft cuts
every chain below the last joint they all share; a vertical prismatic torso is such a
joint and stays the torso.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.robots.draft.model_tree import ModelTree

MIN_LEFT = 2  # movable joints each chain keeps below the trunk, else no trunk is cut


@dataclass(frozen=True)
class Trunk:
    """The last joint all chains share (``None``: none) and the shared joints, root first."""

    joint: str | None
    joints: tuple[str, ...] = ()


def find_trunk(tree: ModelTree, ends: list[str]) -> Trunk:
    """The joints shared by the chains to ``ends`` (hand and camera links), two at least."""
    chains = [[j.name for j in tree.movable_ancestors(end)] for end in ends]
    if len(chains) < 2:
        return Trunk(None)
    shared: list[str] = []
    for names in zip(*chains, strict=False):
        if any(name != names[0] for name in names):
            break
        shared.append(names[0])
    if not shared or any(len(chain) - len(shared) < MIN_LEFT for chain in chains):
        return Trunk(None)
    return Trunk(shared[-1], tuple(shared))

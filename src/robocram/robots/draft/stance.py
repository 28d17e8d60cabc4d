"""A legged robot's standing pose: its feet under its hips, as an animal stands.

A URDF's zero pose is where its joints read 0, not how the robot stands. The B1's calves
cannot straighten (their limit nearest zero is -0.6 rad, where the world starts them), so
at rest each foot stands 0.20 m ahead of its hip, the front feet 0.58 m ahead of the
trunk's origin, and every stand at a counter is that much farther off. Where the feet's
middle stands off the hips' middle by more than :data:`OFF_CENTRE` (fore and aft, in the
root link), the draft turns each leg's first pitch joint (about the root's y) so that its
foot comes under its hip, within limits. Legs splayed about the hips (ANYmal's: the front
feet ahead, the hind ones behind, their middle under the hips') or standing under them
already (Centauro's, TALOS's) stay as the URDF has them.
"""

from __future__ import annotations

import math
from collections.abc import Collection
from dataclasses import dataclass

import numpy as np

from robocram.robots.draft.hands import LEG_WORDS
from robocram.robots.draft.link_poses import axis_in_root, link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.model_pose import resting_value
from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Joint

OFF_CENTRE = 0.03  # [m] the feet's middle this far ahead of or behind the hips': turned
PITCH = 0.9  # |y| of a joint's unit axis (root link) above which it swings the leg fore-aft
BELOW = 0.1  # [m] a leg's foot stands at least this far below its hip
UNDER = 0.005  # [m] a turned foot stands at most this far ahead of or behind its hip


@dataclass(frozen=True)
class Leg:
    """One leg: its first pitch joint (the hip), its foot (its lowest link), and how far
    [m] the foot stands ahead of the hip at rest (negative: behind)."""

    hip: Joint
    foot: str
    ahead: float


@dataclass(frozen=True)
class Stance:
    """The drafted stance: the hips' values [rad], why, and the doubt left (None: none)."""

    values: dict[str, float]
    why: str
    doubt: str | None = None


def legs(model: RobotModel, hands: Collection[str]) -> list[Leg]:
    """The legs hanging from the root's body: chains off it named like legs (``LEG_WORDS``),
    holding none of the ``hands`` (end-effector links), whose lowest link (the foot) stands
    below a joint swinging it fore and aft (the hip)."""
    tree = ModelTree(model)
    rest = _rest(model)
    poses = link_poses(model, rest)
    body = tree.rigid_group(model.root_link)
    found = []
    for top in (j for link in body for j in tree.child_joints(link)):
        if not top.movable:
            continue
        below = [top, *tree.subtree_joints(top.child)]
        names = " ".join(n.lower() for j in below for n in (j.name, j.child))
        if any(j.child in hands for j in below) or not any(w in names for w in LEG_WORDS):
            continue
        foot = min((j.child for j in below), key=lambda link: poses[link].position[2])
        chain = [j for j in model.chain(model.root_link, foot) if j.movable]
        pitch = [j for j in chain if abs(axis_in_root(model, j.name, poses)[1]) > PITCH]
        if not pitch:
            continue
        hip, at = pitch[0], poses[foot].position
        origin = (poses[pitch[0].parent] * hip.origin).position
        if origin[2] - at[2] >= BELOW:
            found.append(Leg(hip, foot, float(at[0] - origin[0])))
    return found


def drafted_stance(model: RobotModel, hands: Collection[str]) -> Stance | None:
    """The hips' values that put every foot under its hip, where the feet's middle stands
    off the hips' (see the module docstring); None where the legs stand as they are."""
    found = legs(model, hands)
    if not found:
        return None
    off = float(np.mean([leg.ahead for leg in found]))
    if abs(off) <= OFF_CENTRE:
        return None
    rest = _rest(model)
    values, missed = {}, []
    for leg in found:
        value = _under_hip(model, leg, rest)
        if value is None:
            missed.append(leg.hip.name)
        else:
            values[leg.hip.name] = value
    way = "ahead of" if off > 0 else "behind"
    why = (
        f"legs: at the URDF's rest (each joint at its value nearest 0) the feet stand "
        f"{abs(off):.2f} m {way} their hips on average; each hip turned to put its foot "
        "under it, as a standing animal's"
    )
    doubt = None
    if missed:
        doubt = f"no value within limits puts the foot under {', '.join(missed)}: set them"
    return Stance(values, why, doubt) if values else None


def _under_hip(model: RobotModel, leg: Leg, rest: dict[str, float]) -> float | None:
    """The hip's value [rad, 3 decimals, within limits] nearest its rest that puts the foot
    under it (within :data:`UNDER`), the leg's other joints at rest; None if none does."""
    poses = link_poses(model, rest)
    hip = leg.hip
    origin = (poses[hip.parent] * hip.origin).position
    axis = axis_in_root(model, hip.name, poses)
    r = np.asarray(poses[leg.foot].position) - np.asarray(origin)
    along = float(r @ axis) * axis
    across = r - along
    turned = np.cross(axis, across)
    # the foot's x after a turn by t: across.x cos t + turned.x sin t + along.x = 0
    a, b, c = float(across[0]), float(turned[0]), float(along[0])
    size = math.hypot(a, b)
    if size < 1e-9 or abs(c) > size:
        return None
    phase, spread = math.atan2(b, a), math.acos(-c / size)
    start = rest[hip.name]
    lower = -math.inf if hip.lower is None else hip.lower
    upper = math.inf if hip.upper is None else hip.upper
    candidates = []
    for root in (phase + spread, phase - spread):
        turn = math.remainder(root, 2 * math.pi)
        value = round(start + turn, 3)
        if not lower <= value <= upper:
            continue
        foot = link_poses(model, {**rest, hip.name: value})[leg.foot].position
        if abs(foot[0] - origin[0]) <= UNDER and foot[2] < origin[2]:
            candidates.append(value)
    return min(candidates, key=lambda v: abs(v - start), default=None)


def _rest(model: RobotModel) -> dict[str, float]:
    """Every joint a mimic does not move at its value nearest 0 (where the world starts it);
    mimic joints follow their masters."""
    return {
        j.name: resting_value(j) for j in model.joints.values() if j.movable and j.mimic is None
    }

"""How a drafted robot's base drives, read from its wheels.

Two driven wheels on one axle (their joints turn about one horizontal line, both fixed to
the body) can only drive forward, backward and turn: a differential base (Stretch, the
Fetch, TIAGo). Wheels on steering joints (the PR2's casters, the HSR's turning drive unit)
or four fixed wheels (mecanum, TIAGo Pro's) drive any way: holonomic. A lone arm is
fixed: a root link called ``world`` (the URDF bolts it there; unless a link is named like
a mobile base, as Armar6's platform), or one chain of joints with no wheels on a mount no
wider than :data:`MOUNT` (a Kinova, an SO-100), the chain ending in one joint or in the
fingers of one hand (a Panda's two fingers: no second arm, head or leg branches off it).
A body with no wheels standing on a link named a pedestal, rigid with its root, is fixed
too (Baxter's; unless a link is named like a mobile base). Any other URDF with no wheels
says nothing; the draft keeps the holonomic default and marks the doubt.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from robocram.robots.description import BaseType
from robocram.robots.draft.link_poses import axis_in_root, link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.link_centre import link_box
from robocram.robots.urdf_elements import Joint

HORIZONTAL = 0.1  # |z| of a unit axis in the root link below which it is horizontal
VERTICAL = 0.9  # |z| above which it is vertical (a steering joint)
COAXIAL = 0.01  # [m] two wheel origins this close to one axis line share the axle
MIN_TRACK = 0.1  # [m] between the wheels of one axle
LOW = 0.3  # [m] a wheel's axle is at most this high over the lowest link (the floor)
MOUNT = 0.3  # [m] a lone arm's root is no wider than this: an arm's mount, not a platform
HAND = 0.25  # [m] a lone arm's fingers: every link they move starts this near its wrist
PEDESTAL_WORDS = ("pedestal",)  # a link so named, rigid with the root, is the robot's stand
MOBILE_WORDS = ("platform", "mobile", "omni", "wheel", "caster", "footprint")  # a link so
# named is a mobile base, even under a root called 'world' (Armar6's platform)


@dataclass(frozen=True)
class BaseDrive:
    """The drafted base type, why, and the doubt left."""

    base_type: BaseType
    why: str
    doubt: str | None = None


def _turns_freely(joint: Joint) -> bool:
    """A continuous joint, or a revolute one whose range is at least a full turn."""
    if joint.type == "continuous":
        return True
    lower, upper = joint.lower, joint.upper
    return joint.type == "revolute" and (lower is None or upper is None or upper - lower >= 6.28)


def _wheels(tree: ModelTree, links: set[str]) -> list[Joint]:
    """Leaf joints below ``links`` that turn freely about a low horizontal axis: wheels."""
    model, poses = tree.model, link_poses(tree.model)
    floor = min(pose.position[2] for pose in poses.values())
    return [
        joint
        for joint in model.joints.values()
        if joint.parent in links
        and joint.mimic is None
        and (poses[joint.parent] * joint.origin).position[2] <= floor + LOW
        and _turns_freely(joint)
        and abs(axis_in_root(model, joint.name, poses)[2]) < HORIZONTAL
        and not any(j.movable for j in tree.subtree_joints(joint.child))
    ]


def _axles(tree: ModelTree, wheels: list[Joint]) -> list[tuple[Joint, Joint]]:
    """Pairs of ``wheels`` turning about one line, at least :data:`MIN_TRACK` apart."""
    model, poses = tree.model, link_poses(tree.model)
    pairs = []
    for a, b in itertools.combinations(wheels, 2):
        axis = axis_in_root(model, a.name, poses)
        if abs(float(axis @ axis_in_root(model, b.name, poses))) < 0.99:
            continue
        apart = np.subtract(
            (poses[b.parent] * b.origin).position, (poses[a.parent] * a.origin).position
        )
        off_axis = apart - (apart @ axis) * axis
        if np.linalg.norm(off_axis) < COAXIAL and abs(float(apart @ axis)) >= MIN_TRACK:
            pairs.append((a, b))
    return pairs


def _steered(tree: ModelTree, body: set[str]) -> list[Joint]:
    """Joints on the body that turn freely about a vertical axis and carry a wheel right
    below (an arm's shoulder pan carries its whole arm, whose wrist may look like one)."""
    model, poses = tree.model, link_poses(tree.model)
    return [
        joint
        for joint in model.joints.values()
        if joint.parent in body
        and _turns_freely(joint)
        and abs(axis_in_root(model, joint.name, poses)[2]) > VERTICAL
        and _wheels(tree, set(tree.fixed_closure(joint.child)))
    ]


def find_base_drive(tree: ModelTree) -> BaseDrive:
    """The base type the wheels say (see the module docstring)."""
    model = tree.model
    planar = [j.name for j in model.joints.values() if j.type == "planar"]
    if planar:
        return BaseDrive("holonomic", f"planar joint {planar[0]} moves the base any way")
    body = tree.rigid_group(model.root_link)
    lone = _lone_arm(tree, body)  # before the wheels: a wrist's last joint may look like one
    if lone is not None:
        doubt = "say 'holonomic' (or 'differential') if the arm rides on a mobile base"
        return BaseDrive("fixed", lone, doubt)
    fixed = _wheels(tree, body)
    axles = _axles(tree, fixed)
    if len(fixed) == 2 and len(axles) == 1:
        left, right = axles[0]
        why = f"{left.name} and {right.name} drive two wheels on one axle: no sideways motion"
        return BaseDrive("differential", why)
    steered = _steered(tree, body)
    if steered:
        names = ", ".join(j.name for j in steered)
        return BaseDrive("holonomic", f"wheels on steering joints ({names}) drive any way")
    if len(fixed) >= 4 and len(axles) >= 2:
        names = ", ".join(j.name for j in fixed)
        why = f"{len(fixed)} wheels on fixed axles ({names}): mecanum wheels drive any way"
        doubt = "skid-steered wheels would not: then say base_type='differential'"
        return BaseDrive("holonomic", why, doubt)
    pedestal = _pedestal(tree, body)
    if pedestal is not None:
        doubt = "say 'holonomic' (or 'differential') if the pedestal rolls on driven wheels"
        return BaseDrive("fixed", pedestal, doubt)
    doubt = (
        "holonomic assumed; say 'differential' for two wheels "
        "on one axle, 'fixed' for a base that stays"
    )
    return BaseDrive("holonomic", "no driven wheels in the URDF: the default", doubt)


def _pedestal(tree: ModelTree, body: set[str]) -> str | None:
    """Why the robot stands on a pedestal, or None: a link rigid with the root is named
    like one and none is named like a mobile base (the caller found no driven wheels)."""
    model = tree.model
    if any(any(w in k.lower() for w in MOBILE_WORDS) for k in model.links):
        return None
    stands = sorted(k for k in body if any(w in k.lower() for w in PEDESTAL_WORDS))
    if not stands:
        return None
    return f"it stands on {stands[0]}, rigid with its root, and has no driven wheels: fixed"


def _hand_chain(tree: ModelTree, movable: list[Joint]) -> tuple[list[Joint], int] | None:
    """The movable joints every leaf joint hangs from, root first, and how many fingers
    branch off the last of them; None unless the branches are one hand's fingers (each
    link they move starts within :data:`HAND` of the chain's last link: a second arm or a
    head branching off a torso reaches farther)."""
    leaves = [j for j in movable if not any(k.movable for k in tree.subtree_joints(j.child))]
    chains = [tree.movable_ancestors(leaf.child) for leaf in leaves]
    common: list[Joint] = []
    for joints in zip(*chains, strict=False):
        if len({joint.name for joint in joints}) != 1:
            break
        common.append(joints[0])
    if not common:
        return None
    names = {joint.name for joint in common}
    fingers = [joint for joint in movable if joint.name not in names]
    poses = link_poses(tree.model)
    wrist = np.asarray(poses[common[-1].child].position)
    for joint in fingers:
        if np.linalg.norm(np.asarray(poses[joint.child].position) - wrist) > HAND:
            return None
    return common, len(leaves) if fingers else 0


def _lone_arm(tree: ModelTree, body: set[str]) -> str | None:
    """Why the robot is an arm fixed where it stands, or None: its root link is called
    ``world`` (and no link is named like a mobile base), or its movable joints form one
    chain, ending in one joint or in one hand's fingers, from a mount no wider than
    :data:`MOUNT` (a platform under it would be a mobile base the URDF does not drive)."""
    model = tree.model
    mobile = [k for k in model.links if any(w in k.lower() for w in MOBILE_WORDS)]
    if model.root_link.lower() == "world" and not mobile:
        return "the URDF's root link is 'world': the robot is fixed to it"
    movable = [j for j in model.joints.values() if j.movable]
    found = _hand_chain(tree, movable)
    if found is None:
        return None
    chain, fingers = found
    boxes = [box for link in body if (box := link_box(model.link(link))) is not None]
    width = max((max(h[0] - l[0], h[1] - l[1]) for l, h in boxes), default=0.0)
    if width > MOUNT:
        return None
    if not fingers:
        return f"one chain of {len(chain)} joints on a {width:.2f} m mount, no wheels: a lone arm"
    return (
        f"one chain of {len(chain)} joints ending in a hand of {fingers} fingers, on a "
        f"{width:.2f} m mount, no wheels, legs, head or second arm: a lone arm"
    )

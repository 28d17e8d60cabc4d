"""Find the hands of a URDF: gripper-like ends of joint chains, their fingers and grippers.

A hand hangs below the last joint of an arm (at least :data:`MIN_ARM_JOINTS` movable joints
from the root) and is where finger joints start: the first movable joints below the wrist
link include a finger, which is prismatic, coupled by ``<mimic>``, or a leaf. The gripper
joints are the masters the most other hand joints mimic; without mimics, the finger joints.

A robot with no such hand may still have arms: chains of at least :data:`MIN_ARM_JOINTS`
joints whose last joint moves nothing below it (a UR's flange, a Kinova with its fingers
fixed, a ball). :func:`find_fixed_hands` gives those ends as hands without fingers, which
the draft describes as suction grippers; chains named like legs or wheels are left out.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.urdf_elements import Joint

MIN_ARM_JOINTS = 4  # movable joints from the root to the wrist: fewer is no arm
MANY_FINGERS = 3  # chains of phalanges below one link that make it a hand
MAX_PHALANGES = 4  # joints of one finger, at most (a human finger has 3 or 4)


@dataclass(frozen=True)
class Hand:
    """One gripper-like end: the wrist link, its hand joints and the gripper joints."""

    wrist_joint: str  # the last arm joint
    end_effector_link: str  # its child: the link the hand is fixed to
    hand_joints: tuple[str, ...]  # every movable joint below the wrist link
    gripper_joints: tuple[str, ...]  # the ones a plan commands
    gripper_links: tuple[str, ...]  # links the gripper joints move
    hand_links: tuple[str, ...]  # every link below the wrist link
    why_gripper: str
    doubt_gripper: str | None = None
    opens_at_lower: bool = False  # curling fingers: open straight (0), closed curled
    fixed: bool = False  # no moving finger: it can only hold what it touches (suction)


FINGER_WORDS = ("finger", "gripper", "jaw", "thumb", "hand")  # in a lone leaf joint's name
LEG_WORDS = ("wheel", "foot", "leg", "hip", "knee", "ankle", "shank", "thigh", "toe", "caster")


def _leaf(tree: ModelTree, joint: Joint) -> bool:
    return not any(j.movable for j in tree.subtree_joints(joint.child))


def _moves_nothing_else(tree: ModelTree, joint: Joint) -> bool:
    """Whether every movable joint below ``joint`` is coupled by ``<mimic>``."""
    below = [j for j in tree.subtree_joints(joint.child) if j.movable]
    return all(j.mimic is not None or tree.is_mimicked(j.name) for j in below)


def _finger_like(tree: ModelTree, joint: Joint, siblings: int) -> bool:
    """Prismatic, coupled by a mimic, or a leaf beside other fingers (or named like one),
    and carrying no joint of its own.

    A lone revolute leaf is a wrist's last joint (UR, xArm) unless its name says gripper.
    """
    if not _moves_nothing_else(tree, joint):
        return False
    if joint.type == "prismatic" or joint.mimic is not None or tree.is_mimicked(joint.name):
        return True
    if not _leaf(tree, joint):
        return False
    return siblings >= 2 or any(word in joint.name.lower() for word in FINGER_WORDS)


def _finger_chain(tree: ModelTree, joint: Joint) -> bool:
    """Whether ``joint`` starts a finger of a many-fingered hand: a chain of at most
    :data:`MAX_PHALANGES` revolute joints, one after the other, with nothing branching."""
    chain = [j for j in tree.subtree_joints(joint.child) if j.movable]
    if joint.type not in ("revolute", "continuous") or len(chain) >= MAX_PHALANGES:
        return False
    links = [joint.child, *(j.child for j in chain)]
    return all(len([j for j in tree.movable_roots(link) if j.movable]) <= 1 for link in links)


def _fingers(tree: ModelTree, link: str) -> list[Joint]:
    """The finger joints among the first movable joints below ``link``: prismatic, coupled or
    leaves (a gripper's); else, where at least :data:`MANY_FINGERS` chains of phalanges start
    (Armar6's, Justin's, Alex's five- and four-fingered hands), those chains' first joints."""
    roots = tree.movable_roots(link)
    found = [root for root in roots if _finger_like(tree, root, len(roots))]
    if found:
        return found
    chains = [root for root in roots if _finger_chain(tree, root)]
    return chains if len(chains) >= MANY_FINGERS else []


def _is_hand(tree: ModelTree, joint: Joint) -> bool:
    if not joint.movable or joint.mimic is not None or tree.is_mimicked(joint.name):
        return False
    if len(tree.movable_ancestors(joint.child)) < MIN_ARM_JOINTS:
        return False
    return bool(_fingers(tree, joint.child))


def find_hands(tree: ModelTree) -> list[Hand]:
    """The hands of the model, in file order; a hand below another hand's wrist is a finger."""
    wrists = [j for j in tree.model.joints.values() if _is_hand(tree, j)]
    highest = [
        w for w in wrists if not any(o is not w and tree.below(o.child, w.child) for o in wrists)
    ]
    return [_hand(tree, wrist) for wrist in highest]


def _gripper_joints(
    tree: ModelTree, link: str, hand_joints: list[Joint]
) -> tuple[tuple[str, ...], str]:
    masters = [j.name for j in hand_joints if j.mimic is None and tree.is_mimicked(j.name)]
    if masters:
        most = max(len(tree.followers(m)) for m in masters)
        chosen = tuple(m for m in masters if len(tree.followers(m)) == most)
        return chosen, f"mimicked by {most} hand joint(s) (<mimic> in the URDF)"
    fingers = tuple(j.name for j in _fingers(tree, link) if j.mimic is None)
    curls = _curls(hand_joints)
    if len(curls) > len(fingers):
        why = f"no <mimic> couples the hand: its {len(curls)} curling joints move together"
        return curls, why
    return fingers, "the finger joints (prismatic, or leaves) right below the wrist"


def _curls(hand_joints: list[Joint]) -> tuple[str, ...]:
    """Revolute joints straight at 0 that bend one way, to their upper limit.

    A hand whose URDF does not couple its fingers (a simulator plugin does) curls them so:
    the description opens them at 0 and closes them at the upper limit, all together.
    """
    return tuple(
        j.name
        for j in hand_joints
        if j.type == "revolute"
        and j.mimic is None
        and j.lower == 0.0
        and j.upper is not None
        and j.upper > 0.0
    )


def _hand(tree: ModelTree, wrist: Joint) -> Hand:
    link = wrist.child
    hand_joints = [j for j in tree.subtree_joints(link) if j.movable]
    gripper, why = _gripper_joints(tree, link, hand_joints)
    moving = [*gripper, *(f for g in gripper for f in tree.followers(g))]
    children = [tree.model.joints[joint].child for joint in moving]
    gripper_links = tuple(
        dict.fromkeys(name for child in children for name in (child, *tree.subtree_links(child)))
    )
    others = [j.name for j in hand_joints if j.name not in moving]
    doubt = None
    if others:
        doubt = (
            f"{len(others)} more hand joint(s) move with no gripper joint: "
            f"{', '.join(others[:6])}{', ...' if len(others) > 6 else ''}; couple them "
            "(<mimic> or the gripper model) if they are fingers"
        )
    return Hand(
        wrist_joint=wrist.name,
        end_effector_link=link,
        hand_joints=tuple(j.name for j in hand_joints),
        gripper_joints=gripper,
        gripper_links=gripper_links,
        hand_links=tuple(tree.subtree_links(link)),
        why_gripper=why,
        doubt_gripper=doubt,
        opens_at_lower=why.startswith("no <mimic> couples"),
    )


def find_fixed_hands(tree: ModelTree) -> list[Hand]:
    """Arm ends with no moving finger, in file order: the last joint of a chain of at least
    :data:`MIN_ARM_JOINTS` movable joints, with nothing movable below it, named like no leg
    or wheel (a legged or wheeled base's chains end so too)."""
    found = []
    for joint in tree.model.joints.values():
        if not joint.movable or joint.mimic is not None or not _leaf(tree, joint):
            continue
        chain = tree.movable_ancestors(joint.child)
        if len(chain) < MIN_ARM_JOINTS:
            continue
        names = [n for j in chain for n in (j.name, j.child)] + tree.subtree_links(joint.child)
        if any(word in name.lower() for name in names for word in LEG_WORDS):
            continue
        found.append(
            Hand(
                wrist_joint=joint.name,
                end_effector_link=joint.child,
                hand_joints=(),
                gripper_joints=(),
                gripper_links=(),
                hand_links=tuple(tree.subtree_links(joint.child)),
                why_gripper=f"no finger joint moves below {joint.child}",
                fixed=True,
            )
        )
    return found

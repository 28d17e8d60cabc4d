"""The arms of a drafted robot: chains from the torso (or root) to each hand, named by side.

Two alike arms (as many joints of the same types) side by side are ``left`` (larger y)
and ``right``; one hand is ``arm``; other layouts are ``arm_1``, ``arm_2``, ... with a doubt.
A hand without moving fingers gets a suction gripper and a tool frame on its tip, with a
doubt saying so.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from robocram.robots.description import ArmDescription
from robocram.robots.draft.finger_spread import opens_at_upper
from robocram.robots.draft.hands import Hand
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.draft.loaded_hand import hand_as_loaded
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.draft.stowing import drafted_parking
from robocram.robots.draft.tool_frames import approach_and_opening, tool_frame
from robocram.robots.draft.tool_tips import tip_frame
from robocram.robots.gripper import GripperDescription, GripperJoint
from robocram.robots.model_additions import FrameSpec

SIDE_GAP = 0.1  # [m] between two alike hands' y for one to be left of the other


@dataclass(frozen=True)
class DraftedArm:
    """One arm's description, the frame it adds, and why per field (``doubts`` to check)."""

    arm: ArmDescription
    added: FrameSpec | None
    why: dict[str, str] = field(default_factory=dict)
    doubts: dict[str, str] = field(default_factory=dict)


def arm_names(tree: ModelTree, hands: list[Hand]) -> tuple[list[str], str, str | None]:
    """Names for ``hands`` in order, why, and a doubt if the layout is unclear."""
    if len(hands) == 1:
        return ["arm"], "one gripper-like end", None
    poses = link_poses(tree.model)
    ys = [poses[h.end_effector_link].position[1] for h in hands]
    shapes = [[j.type for j in tree.movable_ancestors(h.end_effector_link)] for h in hands]
    if len(hands) == 2 and shapes[0] == shapes[1] and abs(ys[0] - ys[1]) > SIDE_GAP:
        names = ["left", "right"] if ys[0] > ys[1] else ["right", "left"]
        return names, f"two alike arms {abs(ys[0] - ys[1]):.3f} m apart (left: larger y)", None
    names = [f"arm_{i + 1}" for i in range(len(hands))]
    return names, f"{len(hands)} gripper-like ends", "name the arms and give their sides"


def _closing_upwards(tree: ModelTree, hand: Hand) -> list[str]:
    """The gripper joints whose fingers stand closer together at the upper limit."""
    approach, _ = approach_and_opening(tree, hand)
    return [j for j in hand.gripper_joints if opens_at_upper(tree, hand, j, approach) is False]


def _gripper(tree: ModelTree, hand: Hand, reversed_joints: list[str]) -> GripperDescription:
    """The gripper opening each joint at the limit where its fingers stand wider."""
    joints = []
    for name in hand.gripper_joints:
        spec = tree.model.joints[name]
        lower, upper = spec.lower or 0.0, spec.upper or 0.0
        opened, closed = (lower, upper) if name in reversed_joints else (upper, lower)
        joints.append(GripperJoint(name, open=opened, closed=closed))
    return GripperDescription(tuple(joints))


SUCTION_DOUBT = (
    "no finger joint moves below {wrist}: drafted as a fixed, suction-like end effector that "
    "holds what its tool frame (on the hand's tip) touches, from above; if the hand has "
    "fingers, give their joints as gripper_joints (or a GripperDescription) instead"
)


def _arm_joints(tree: ModelTree, hand: Hand, torso: str | None) -> tuple[str, ...]:
    """The arm's joints: the movable ancestors of the wrist after the torso, no mimics."""
    chain = tree.movable_ancestors(hand.end_effector_link)
    names = [j.name for j in chain]
    if torso in names:
        chain = chain[names.index(torso) + 1 :]
    return tuple(j.name for j in chain if j.mimic is None)


def draft_fixed_arm(tree: ModelTree, hand: Hand, name: str, torso: str | None) -> DraftedArm:
    """The arm ending in a hand with no moving finger: a suction gripper on its tip."""
    joints = _arm_joints(tree, hand, torso)
    tool = tip_frame(tree, hand, name)
    parking = drafted_parking(tree.model, joints, hand.end_effector_link)
    arm = ArmDescription(
        name=name,
        end_effector_link=hand.end_effector_link,
        tool_frame=tool.name,
        base_link=tree.model.joints[joints[0]].parent,
        joints=joints,
        parking=parking.values,
        side=name if name in ("left", "right") else None,
        gripper=GripperDescription.suction(),
    )
    why = {
        "end_effector_link": f"child of {hand.wrist_joint}, the chain's last joint",
        "base_link": _base_why(torso),
        "tool_frame": tool.why,
        "gripper": f"{hand.why_gripper}: it holds what its tool frame touches",
        "parking": parking.why,
    }
    doubts = {"gripper": SUCTION_DOUBT.format(wrist=hand.end_effector_link)}
    if parking.doubt:
        doubts["parking"] = parking.doubt
    return DraftedArm(arm, tool.added, why, doubts)


def _base_why(torso: str | None) -> str:
    """Why the arm's base link is the one drafted (the same for every kind of hand)."""
    after = " after the torso" if torso else ""
    return f"parent of the first arm joint{after}; its joints down to the wrist are found at load"


def draft_arm(tree: ModelTree, hand: Hand, name: str, torso: str | None) -> DraftedArm:
    """The arm ending in ``hand``: chain joints after the torso, tool frame, parking."""
    if hand.fixed:
        return draft_fixed_arm(tree, hand, name, torso)
    joints = _arm_joints(tree, hand, torso)
    base = tree.model.joints[joints[0]].parent
    tool = tool_frame(tree, hand, name)
    reversed_joints = (
        list(hand.gripper_joints) if hand.opens_at_lower else _closing_upwards(tree, hand)
    )
    gripper = _gripper(tree, hand, reversed_joints) if reversed_joints else None
    if hand.opens_at_lower:
        gripper = GripperDescription.curling()  # the same joints, found again at load
    arm = ArmDescription(
        name=name,
        end_effector_link=hand.end_effector_link,
        tool_frame=tool.name,
        base_link=base,
        joints=joints,
        gripper_joints=() if gripper else hand.gripper_joints,
        side=name if name in ("left", "right") else None,
        gripper=gripper,
    )
    loaded = hand_as_loaded(tree.model, arm, tool.added)
    parking = drafted_parking(loaded, joints, hand.end_effector_link)
    arm = replace(arm, parking=parking.values)
    why = {
        "end_effector_link": f"child of {hand.wrist_joint}, the last joint before the fingers",
        "base_link": _base_why(torso),
        "tool_frame": tool.why,
        "gripper_joints": hand.why_gripper + "; fingers and hand links are found at load",
        "gripper": f"{hand.why_gripper}; open at the lower limit, where the fingers part",
        "parking": parking.why,
    }
    doubts = {"parking": parking.doubt} if parking.doubt else {}
    if hand.doubt_gripper:
        doubts["gripper_joints"] = hand.doubt_gripper
    if tool.doubt:
        doubts["tool_frame"] = tool.doubt
    if gripper is not None and "gripper_joints" in doubts:
        doubts["gripper"] = doubts.pop("gripper_joints")  # printed with the gripper
    return DraftedArm(arm, tool.added, why, doubts)

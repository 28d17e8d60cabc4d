"""The tool frame of a drafted arm, in robocram's convention: x = approach, y = opening.

The approach is the direction from the wrist link to the middle of the hand's links; the
opening is how the finger that moves most moves when the gripper opens (the joints'
upper limits). A jaw turning about its own frame's origin against a fixed jaw (Unitree's
Z1, the SO-101) moves no link frame: there the middles of the links' collision shapes
are measured, the opening points the way the jaw opens, and an added frame sits in the
middle of the opening, between the fixed jaw's inner face and the moving jaw open
(``jaw_opening.py``; the closed jaw's middle lies inside the fixed jaw). An existing
frame rigid with the wrist, named like a tool frame and reaching the fingers, is kept
when its axes agree; otherwise a frame is added in code, along the approach amid the
outer half of the closed fingers' shapes (a finger link's frame can sit on the gripper's
base, as the TIAGo Pro's do); a curling hand's at its links' reach, as before.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from robocram.robots.draft.finger_spread import opens_at_upper
from robocram.robots.draft.hands import Hand
from robocram.robots.draft.jaw_opening import jaw_opening_centre, shape_points
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.link_centre import link_centre
from robocram.robots.model_additions import FrameSpec
from robocram.tf import Pose

TOOL_WORDS = ("tool", "tcp", "grasp", "endpoint", "end_effector", "gripper")
AXIS_AGREEMENT = math.cos(math.radians(20.0))  # an axis within 20 degrees of the wanted one
SNAP = math.cos(math.radians(15.0))  # a measured direction this close to a link axis is it
REACH_SHARE = 0.9  # of the fingers' reach past the wrist a kept tool frame must reach
FINGER_REACH = 0.01  # [m] a finger's shape middle this far from its frame shows its reach


@dataclass(frozen=True)
class ToolFrame:
    """The arm's tool frame: a URDF frame, or one to add (``added``), and why."""

    name: str
    added: FrameSpec | None
    why: str
    doubt: str | None = None


def _snapped(direction: np.ndarray) -> np.ndarray:
    unit = direction / np.linalg.norm(direction)
    best = int(np.argmax(np.abs(unit)))
    if abs(unit[best]) >= SNAP:
        snapped = np.zeros(3)
        snapped[best] = math.copysign(1.0, unit[best])
        return snapped
    return unit


def _in_wrist(
    tree: ModelTree, hand: Hand, values: dict[str, float], centres: bool = False
) -> dict[str, np.ndarray]:
    """Positions [m] of the hand's links (frames, or shape middles) in the wrist link."""
    poses = link_poses(tree.model, values)
    wrist = poses[hand.end_effector_link].inverse()

    def point(link: str) -> np.ndarray:
        at = Pose(link_centre(tree.model.link(link))) if centres else Pose()
        return np.asarray((wrist * poses[link] * at).position)

    return {link: point(link) for link in hand.hand_links}


def _closed(tree: ModelTree, hand: Hand, jaw: bool) -> dict[str, float]:
    """The gripper joints where the fingers close: the lower limits, or a turning jaw's own."""
    if not jaw:
        return _gripper_at(tree, hand, "closed")
    return _gripper_at(tree, hand, "open" if _upper_closes(tree, hand) else "closed")


def _upper_closes(tree: ModelTree, hand: Hand) -> bool:
    """Whether a turning jaw closes at its joints' upper limits (the Z1's does)."""
    approach, _ = approach_and_opening(tree, hand)
    return opens_at_upper(tree, hand, hand.gripper_joints[0], approach) is False


def _gripper_at(tree: ModelTree, hand: Hand, where: str) -> dict[str, float]:
    values = {}
    for name in hand.gripper_joints:
        joint = tree.model.joints[name]
        limit = joint.upper if where == "open" else joint.lower
        values[name] = limit if limit is not None and math.isfinite(limit) else 0.0
    return values


def _pivots(tree: ModelTree, hand: Hand, opened: dict[str, np.ndarray]) -> bool:
    """Whether ``hand``'s fingers turn about their own frames (which stay put between open,
    ``opened``, and closed) and have collision shapes to measure their bodies on."""
    closed = _in_wrist(tree, hand, _gripper_at(tree, hand, "closed"))
    links = hand.gripper_links
    still = all(np.linalg.norm(opened[k] - closed[k]) < 1e-6 for k in links)
    return bool(links) and still and all(tree.model.link(k).collisions for k in links)


def approach_and_opening(tree: ModelTree, hand: Hand) -> tuple[np.ndarray, np.ndarray | None]:
    """Unit approach and opening directions in the wrist link (opening None if unseen)."""
    approach = _finger_extension(tree, hand)
    if approach is None:
        opened = _in_wrist(tree, hand, _gripper_at(tree, hand, "open"))
        approach = _snapped(np.mean(list(opened.values()), axis=0))
        if np.max(np.abs(approach)) < 1.0 and _pivots(tree, hand, opened):
            # no axis of the wrist within 15 degrees, and the fingers' frames are the pivots
            # they turn about: a jaw's pivot off to the side (the SO-100's) says little; the
            # middle of the hand's bodies at the URDF's zeros, the wrist link's (a fixed
            # jaw's) and the fingers', does
            at_zero = _in_wrist(tree, hand, {}, centres=True)
            wrist = np.asarray(link_centre(tree.model.link(hand.end_effector_link)))
            middles = [wrist, *(at_zero[link] for link in hand.gripper_links)]
            approach = _snapped(np.mean(middles, axis=0))
    opening = _opening(tree, hand, approach, centres=False)
    if opening is None:
        opening = _opening(tree, hand, approach, centres=True)
    return approach, opening


def _finger_extension(tree: ModelTree, hand: Hand) -> np.ndarray | None:
    """The way the fingers reach out, from their frames to their shapes' middles, where
    that lies along a wrist axis (within ``SNAP``): a finger is longer than it is thick.
    None where the fingers' shapes sit on their frames or point no clear way; the mean
    of the hand's links decides then (it counts cameras and plates on the wrist too, and
    a wrist camera behind the fingers turns it: IAI's Kevin)."""
    if not hand.gripper_links:
        return None
    values = _gripper_at(tree, hand, "open")
    frames = _in_wrist(tree, hand, values)
    centres = _in_wrist(tree, hand, values, centres=True)
    reach = np.sum([centres[link] - frames[link] for link in hand.gripper_links], axis=0)
    if np.linalg.norm(reach) < FINGER_REACH * len(hand.gripper_links):
        return None
    snapped = _snapped(reach)
    return snapped if np.count_nonzero(snapped) == 1 else None


def turning_jaw(tree: ModelTree, hand: Hand) -> bool:
    """Whether the fingers part only when measured at their shapes' middles."""
    approach, _ = approach_and_opening(tree, hand)
    return _opening(tree, hand, approach, centres=False) is None and (
        _opening(tree, hand, approach, centres=True) is not None
    )


def _opening(tree: ModelTree, hand: Hand, approach: np.ndarray, centres: bool) -> np.ndarray | None:
    """How the finger that moves most moves sideways from closed to the upper limits."""
    opened = _in_wrist(tree, hand, _gripper_at(tree, hand, "open"), centres)
    closed = _in_wrist(tree, hand, _gripper_at(tree, hand, "closed"), centres)
    moves = {link: opened[link] - closed[link] for link in hand.gripper_links}
    if not moves:
        return None
    link = max(moves, key=lambda name: float(np.linalg.norm(moves[name])))
    sideways = moves[link] - (moves[link] @ approach) * approach
    if np.linalg.norm(sideways) < 1e-4:
        return None
    return _snapped(sideways)


def _reach(tree: ModelTree, hand: Hand, approach: np.ndarray, centres: bool) -> float:
    """How far [m] past the wrist along the approach the gripper links reach, closed."""
    closed = _in_wrist(tree, hand, _closed(tree, hand, centres), centres)
    reach = [float(closed[link] @ approach) for link in hand.gripper_links] or [0.0]
    return max(reach)


def _candidates(tree: ModelTree, hand: Hand) -> list[str]:
    rigid = tree.fixed_closure(hand.end_effector_link)[1:]
    return [
        link
        for link in rigid
        if any(word in link.lower() for word in TOOL_WORDS) and "finger" not in link.lower()
    ]


def _orientation(x_axis: np.ndarray, y_axis: np.ndarray) -> Pose:
    y = y_axis - (y_axis @ x_axis) * x_axis
    y /= np.linalg.norm(y)
    matrix = np.eye(4)
    matrix[:3, :3] = np.column_stack((x_axis, y, np.cross(x_axis, y)))
    return Pose.from_matrix(matrix)


def _fallback_opening(approach: np.ndarray) -> np.ndarray:
    axis = int(np.argmin(np.abs(approach)))
    return np.eye(3)[axis]


def _between_jaws(
    tree: ModelTree,
    hand: Hand,
    arm: str,
    directions: tuple[np.ndarray, np.ndarray],
    doubt: str | None,
) -> ToolFrame | None:
    """A one-sided jaw's frame at the middle of its opening (``jaw_opening.py``), or None
    where the shapes show no fixed jaw facing the moving one."""
    upper = _upper_closes(tree, hand)
    closed = _gripper_at(tree, hand, "open" if upper else "closed")
    opened = _gripper_at(tree, hand, "closed" if upper else "open")
    centre = jaw_opening_centre(tree, hand, directions, closed, opened)
    if centre is None:
        return None
    spec = FrameSpec(
        f"{arm}_standard_tool_frame",
        hand.end_effector_link,
        Pose(
            (float(centre[0]), float(centre[1]), float(centre[2])),
            _orientation(*directions).orientation,
        ),
    )
    out = float(centre @ directions[0])
    why = (
        "one jaw turns against a fixed one: added in the middle of the opening between the "
        f"fixed jaw's inner face and the moving jaw open, {out:.3f} m out along the approach"
    )
    return ToolFrame(spec.name, spec, why, doubt)


def tool_frame(tree: ModelTree, hand: Hand, arm: str) -> ToolFrame:
    """An existing tool frame that follows the convention, or one to add and why."""
    approach, opening = approach_and_opening(tree, hand)
    doubt = None
    jaw = turning_jaw(tree, hand)
    if opening is None:
        opening = _fallback_opening(approach)
        doubt = "the fingers did not move apart between the joint limits; check y = opening"
    elif jaw and opens_at_upper(tree, hand, hand.gripper_joints[0], approach) is False:
        opening = -opening  # measured towards the upper limits, where this jaw closes
    if jaw:
        between = _between_jaws(tree, hand, arm, (approach, opening), doubt)
        if between is not None:
            return between
    reach = _reach(tree, hand, approach, jaw)
    at_rest = _in_wrist(tree, hand, {})
    poses = link_poses(tree.model)
    wrist = poses[hand.end_effector_link]
    for name in sorted(_candidates(tree, hand), key=lambda n: -float(at_rest[n] @ approach)):
        if float(at_rest[name] @ approach) < REACH_SHARE * reach:
            continue
        frame = wrist.inverse() * poses[name]
        axes = frame.matrix()[:3, :3]
        if axes[:, 0] @ approach >= AXIS_AGREEMENT and abs(axes[:, 1] @ opening) >= AXIS_AGREEMENT:
            return ToolFrame(name, None, "the URDF's frame at the fingers, x = approach", doubt)
        turn = frame.inverse() * Pose(frame.position, _orientation(approach, opening).orientation)
        spec = FrameSpec(f"{arm}_standard_tool_frame", name, Pose(orientation=turn.orientation))
        why = f"{name} is at the fingers but its axes differ: turned to x = approach, y = opening"
        return ToolFrame(spec.name, spec, why, doubt)
    closed = _in_wrist(tree, hand, _closed(tree, hand, jaw), jaw)
    middle = np.mean([closed[link] for link in hand.gripper_links] or [approach * reach], axis=0)
    grip = None if jaw or hand.opens_at_lower else _grip_depth(tree, hand, approach)
    depth = reach if grip is None else grip
    centre = middle + (depth - float(middle @ approach)) * approach
    spec = FrameSpec(
        f"{arm}_standard_tool_frame",
        hand.end_effector_link,
        Pose(tuple(float(v) for v in centre), _orientation(approach, opening).orientation),  # type: ignore[arg-type]
    )
    where = "" if grip is None else ", amid the outer half of the closed fingers"
    why = (
        f"no frame of the URDF reaches the fingers: added {depth:.3f} m out along the "
        f"approach{where}"
    )
    return ToolFrame(spec.name, spec, why, doubt)


def _shut(tree: ModelTree, hand: Hand, approach: np.ndarray) -> dict[str, float]:
    """The gripper joints at the limits where the fingers stand nearer (lower where the
    shapes cannot tell)."""
    values = {}
    for name in hand.gripper_joints:
        joint = tree.model.joints[name]
        limit = joint.upper if opens_at_upper(tree, hand, name, approach) is False else joint.lower
        values[name] = limit if limit is not None and math.isfinite(limit) else 0.0
    return values


def _grip_depth(tree: ModelTree, hand: Hand, approach: np.ndarray) -> float | None:
    """How far [m] out along ``approach`` the fingers hold what they close on: the middle
    of the outer half of the closed gripper links' shapes, where a jaw holds too
    (``jaw_opening.py``); None where no shape can be read.

    Link frames say little: the Tiago Pro's fingertip links' origins lie at the gripper's
    base, their pads 7 to 64 mm beyond, and a tool frame there put the base 17 mm into a
    mug's handle it grasped (issue 37)."""
    wrist = hand.end_effector_link
    points = shape_points(tree, hand.gripper_links, _shut(tree, hand, approach), wrist)
    if not len(points):
        return None
    along = points @ approach
    return float(along.min() + 3.0 * along.max()) / 4.0

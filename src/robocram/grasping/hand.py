"""A hand as the grasp model sees it: its approach and opening axes and how wide it opens.

The axes are read from the robot's kinematics, not assumed: the approach axis runs from
the wrist (the arm's end-effector link) to the tool frame, the opening axis joins the two
fingers farthest apart with the gripper open (made perpendicular to the approach). Our
convention (x approach, y opening) is what every built-in robot gives. A wrist that sits
off the fingers' line (Kevin's hand hangs 7 cm below its SCARA wrist: the line is 23
degrees off the fingers) would tilt every grasp; beyond :data:`OFF_AXIS_WRIST` the tool
frame's own x is the approach (``robot check`` holds it within 30 degrees of the line).
A suction hand (``GripperDescription.suction()``) has no opening: it holds what its tool
frame touches, so it opens to no width and fits any object it can touch from above.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from itertools import combinations

import numpy as np

from robocram.grasping.errors import GraspingError
from robocram.grasping.pad_reach import pads_behind
from robocram.grasping.palm import Palm, palm_of
from robocram.kinematics import forward_kinematics
from robocram.logic.lru import LRUCache
from robocram.robots import RobotDescription, RobotModel
from robocram.tf import quaternion as quat

OFF_AXIS_WRIST = math.radians(10.0)  # [rad] a wrist-to-tool line this far off the tool's x
FINGER_DEPTH = 0.06  # [m] how far past an object's edge the fingertips may reach
Axis = tuple[float, float, float]


@dataclass(frozen=True)
class Hand:
    """Approach and opening axes (unit, tool frame), widest opening and finger depth [m];
    ``suction``: it holds by touching (no fingers; ``max_opening`` is then infinite);
    ``palm``: a palm hand's palm, which a grasp puts against the object's side (its
    approach the way the fingers curl, its opening the way they point);
    ``pads_behind``: [m] how far behind the tool frame the fingers end, over their stroke
    (negative: past it; ``pad_reach.py``), read for a parallel gripper only."""

    approach: Axis = (1.0, 0.0, 0.0)
    opening: Axis = (0.0, 1.0, 0.0)
    max_opening: float = 0.1
    finger_depth: float = FINGER_DEPTH
    suction: bool = False
    palm: Palm | None = None  # a palm hand's palm (``palm.py``)
    pads_behind: float = 0.0


def _unit(v: np.ndarray, fallback: Axis) -> Axis:
    norm = float(np.linalg.norm(v))
    if norm < 1e-9:
        return fallback
    u = v / norm
    return (float(u[0]), float(u[1]), float(u[2]))


def _opening_axis(desc: RobotDescription, arm: str, approach: np.ndarray) -> Axis:
    spec = desc.arms[arm]
    if spec.gripper is None or spec.gripper.is_suction or len(spec.gripper_links) < 2:
        return _unit(np.cross(approach, (0.0, 0.0, 1.0)), (0.0, 1.0, 0.0))
    tool = forward_kinematics(desc, {}, spec.tool_frame).inverse()
    opened = spec.gripper.at(1.0)
    points = [
        np.asarray((tool * forward_kinematics(desc, opened, link)).position)
        for link in spec.gripper_links
    ]
    a, b = max(combinations(points, 2), key=lambda p: float(np.linalg.norm(p[0] - p[1])))
    spread = (a - b) - float((a - b) @ approach) * approach
    spread = spread if spread[int(np.argmax(np.abs(spread)))] > 0 else -spread
    return _unit(spread, (0.0, 1.0, 0.0))


def approach_axis(desc: RobotDescription, arm: str) -> Axis:
    """The unit approach axis of ``arm``'s tool (tool frame): from the wrist to the tool
    (a suction hand's tool frame on the wrist's own origin, a bare flange: its x)."""
    spec = desc.arms[arm]
    tool = forward_kinematics(desc, {}, spec.tool_frame)
    wrist = forward_kinematics(desc, {}, spec.end_effector_link)
    suction = spec.gripper is not None and spec.gripper.is_suction
    fallback = (1.0, 0.0, 0.0) if suction else (0.0, 0.0, 1.0)  # a flange's face: on the wrist
    measured = _unit(-np.asarray((tool.inverse() * wrist).position), fallback)
    fingers = spec.gripper is not None and not suction
    if fingers and math.acos(max(-1.0, min(1.0, measured[0]))) > OFF_AXIS_WRIST:
        return (1.0, 0.0, 0.0)  # the wrist off the fingers' line: the tool's x (see below)
    return measured


def _cross(a: Axis, b: Axis) -> Axis:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


@lru_cache(maxsize=64)
def _hand_axes(hand: Hand) -> np.ndarray:
    """The hand's approach, opening and third axis as the columns of a matrix."""
    return np.column_stack([hand.approach, hand.opening, _cross(hand.approach, hand.opening)])


def tool_orientation(hand: Hand, approach: Axis, opening: Axis) -> quat.Quaternion:
    """Tool orientation putting the hand's approach and opening axes onto the given ones."""
    grasp_axes = np.column_stack([approach, opening, _cross(approach, opening)])
    return quat.from_matrix(grasp_axes @ _hand_axes(hand).T)


HANDS_KEPT = 16  # descriptions' hands kept per model (one description per world's robot)


class HandCache:
    """The hands of recently asked descriptions of one model, by identity (a description
    is immutable). Kept on the model (``model.derived(HandCache)``), so it lives exactly as
    long as the model and no module holds one.

    Each entry holds its description, so an ``id`` is never reused while it is cached.
    """

    def __init__(self, model: RobotModel | None = None, size: int = HANDS_KEPT) -> None:
        self.entries: LRUCache[tuple[int, str], tuple[RobotDescription, Hand]] = LRUCache(size)

    def get(self, desc: RobotDescription, arm: str) -> Hand:
        """The hand of ``desc``'s ``arm``, read from the kinematics the first time."""
        entry = self.entries.get((id(desc), arm))
        if entry is not None and entry[0] is desc:
            return entry[1]
        hand = self._of_equal(desc, arm) or _read_hand(desc, arm)
        self.entries.put((id(desc), arm), (desc, hand))
        return hand

    def _of_equal(self, desc: RobotDescription, arm: str) -> Hand | None:
        """The hand kept for a description equal to ``desc`` (each scene loads its robot's
        description anew, on the same model: its hands are read once, not per scene)."""
        kept = self.entries.keys()  # a snapshot: get() below reorders the entries
        for key in kept:
            entry = self.entries.get(key) if key[1] == arm else None
            if entry is not None and entry[0] == desc:
                return entry[1]
        return None


def hand_of(desc: RobotDescription, arm: str) -> Hand:
    """The hand of ``desc``'s ``arm`` (remembered on the description's model).

    Raises:
        GraspingError: the arm has no gripper (nothing to grasp with).
    """
    if desc.model is None:  # not loaded: no model to keep it on
        return _read_hand(desc, arm)
    return desc.model.derived(HandCache).get(desc, arm)


def _read_hand(desc: RobotDescription, arm: str) -> Hand:
    spec = desc.arms.get(arm)
    if spec is None:
        raise GraspingError(f"{desc.name} has no arm {arm!r}; arms: {sorted(desc.arms)}")
    if spec.gripper is not None and spec.gripper.is_suction:
        approach = np.asarray(approach_axis(desc, arm))
        opening = _unit(np.cross(approach, (0.0, 0.0, 1.0)), (0.0, 1.0, 0.0))
        axis = (float(approach[0]), float(approach[1]), float(approach[2]))
        return Hand(axis, opening, float("inf"), 0.0, suction=True)
    if spec.gripper is None or spec.gripper.max_opening is None:
        raise GraspingError(
            f"arm {arm!r} of {desc.name} has no gripper with a known max_opening; give its "
            "ArmDescription gripper_joints (max_opening is derived at load)"
        )
    palm = palm_of(desc, arm)
    if palm is not None:
        return Hand(palm.curl, palm.along, float(spec.gripper.max_opening), palm=palm)
    approach = np.asarray(approach_axis(desc, arm))
    axis = (float(approach[0]), float(approach[1]), float(approach[2]))
    return Hand(
        axis,
        _opening_axis(desc, arm, approach),
        float(spec.gripper.max_opening),
        pads_behind=pads_behind(desc, arm, axis),
    )


def palm_hold(desc: RobotDescription, arm: str, half_width: float) -> tuple[Axis, Axis] | None:
    """How ``arm``'s palm hand holds a bar ``half_width`` [m] thick (a handle), in its tool
    frame: the way it approaches (its palm first) and the point the bar's middle is held
    at; None for any other hand."""
    spec = desc.arms.get(arm)
    gripper = None if spec is None else spec.gripper
    if gripper is None or gripper.is_suction or gripper.max_opening is None:
        return None
    palm = hand_of(desc, arm).palm
    if palm is None:
        return None
    return palm.curl, palm.holding(half_width, half_width, flat=False)

"""The tool frame of a hand without moving fingers: on the hand's tip, x out of it.

A fixed (suction-like) hand holds what its tool frame touches, so the frame goes where
the hand's body ends along its approach: the approach is the direction from the wrist to
the links fixed below it (a flange, a cup, fixed fingers), else the wrist joint's axis
pointing away from the joint before it (a roll about the hand's axis, as a UR's or an
xArm's last joint is). The frame sits on that axis through the wrist's origin, where the
hand's collision shapes near the axis end (convex hulls of meshes, as PyBullet collides
them, read through pinocchio as the draft's self-contact check reads them); never behind
the wrist link's frame, where a tool mounts.
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin

from robocram.robots.draft.hands import Hand
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.draft.tool_frames import ToolFrame
from robocram.robots.link_centre import link_centre
from robocram.robots.model_additions import FrameSpec
from robocram.robots.self_contacts import SelfContacts
from robocram.tf import Pose

HOLD_RADIUS = 0.04  # [m] the hand's shapes this near its axis touch what it holds (a
# mug's top is 4.4 cm in radius); fingers spread wider straddle it
MIN_OFFSET = 0.01  # [m] links fixed below the wrist nearer than this give no direction
SNAP = math.cos(math.radians(15.0))  # a direction this close to a link axis is it


def _snapped(direction: np.ndarray) -> np.ndarray:
    unit = direction / np.linalg.norm(direction)
    best = int(np.argmax(np.abs(unit)))
    if abs(unit[best]) < SNAP:
        return unit
    snapped = np.zeros(3)
    snapped[best] = math.copysign(1.0, unit[best])
    return snapped


def _in_wrist(tree: ModelTree, hand: Hand) -> dict[str, Pose]:
    """The poses of the wrist link and the links below it, in the wrist link's frame."""
    poses = link_poses(tree.model)
    wrist = poses[hand.end_effector_link].inverse()
    return {link: wrist * poses[link] for link in (hand.end_effector_link, *hand.hand_links)}


def _shape_points(shape: object) -> tuple[np.ndarray, bool]:
    """A collision shape's hull points [m, shape frame], or its box's corners (False)."""
    points = getattr(shape, "points", None)
    if points is not None and hasattr(shape, "num_points"):  # a mesh's hull, as PyBullet's
        return np.asarray(points(), float), True
    shape.computeLocalAABB()  # type: ignore[attr-defined]
    box = shape.aabb_local  # type: ignore[attr-defined]
    low, high = np.asarray(box.min_, float), np.asarray(box.max_, float)
    corners = [
        (x, y, z) for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])
    ]
    return np.asarray(corners), False


def _shapes(tree: ModelTree, hand: Hand) -> list[tuple[np.ndarray, bool]]:
    """The points [m, wrist frame] of each of the hand's collision shapes: hull vertices
    (the boxes of Kinova's COLLADA fingers reach past them), or box corners (False)."""
    contacts = tree.model.derived(SelfContacts)
    kinematics, geometry = contacts.kinematics, contacts.geometry
    if not kinematics.existFrame(hand.end_effector_link):
        return []
    data = kinematics.createData()
    placed = pin.GeometryData(geometry)
    q = pin.neutral(kinematics)
    pin.framesForwardKinematics(kinematics, data, q)
    pin.updateGeometryPlacements(kinematics, data, geometry, placed, q)
    wrist = data.oMf[kinematics.getFrameId(hand.end_effector_link)].inverse()
    mine = {hand.end_effector_link, *hand.hand_links}
    found = []
    for index, item in enumerate(geometry.geometryObjects):
        if contacts.links[index] in mine:
            placement = wrist * placed.oMg[index]
            points, hull = _shape_points(item.geometry)
            moved = points @ np.asarray(placement.rotation).T + placement.translation
            found.append((moved, hull))
    return found


def _tip(shapes: list[tuple[np.ndarray, bool]], approach: np.ndarray) -> float:
    """[m] how far out along ``approach`` (through the wrist's origin) the hand ends where
    it touches what it holds: the farthest hull point within :data:`HOLD_RADIUS` of the
    axis, or box reaching that near it (a Kinova's fixed fingers, spread wider, straddle a
    mug its palm touches; a UR gripper's closer ones touch it); 0 if none."""
    sides = np.linalg.svd(approach.reshape(1, 3))[2][1:]  # two unit vectors across it
    reach = 0.0
    for points, hull in shapes:
        lateral = points @ sides.T
        if hull:
            near = points[np.linalg.norm(lateral, axis=1) <= HOLD_RADIUS]
        else:
            low, high = lateral.min(axis=0), lateral.max(axis=0)
            crosses = np.all(low <= HOLD_RADIUS) and np.all(high >= -HOLD_RADIUS)
            near = points if crosses else points[:0]
        if len(near):
            reach = max(reach, float((near @ approach).max()))
    return reach


def approach_of(tree: ModelTree, hand: Hand) -> tuple[np.ndarray, str]:
    """The unit approach [wrist frame] and why."""
    poses = _in_wrist(tree, hand)
    below = [np.asarray(poses[link].position) for link in hand.hand_links]
    if below:
        mean = np.mean(below, axis=0)
        if np.linalg.norm(mean) >= MIN_OFFSET:
            return _snapped(mean), "from the wrist towards the links fixed below it"
    joint = tree.model.joints[hand.wrist_joint]
    axis = np.asarray(joint.axis, float) / np.linalg.norm(joint.axis)
    before = np.asarray(joint.origin.inverse().position)  # the joint before, seen from here
    if abs(float(axis @ before)) < MIN_OFFSET:  # beside the axis: the wrist's body says
        before = -np.asarray(link_centre(tree.model.link(joint.child)))
    sign = -1.0 if float(axis @ before) > 0.0 else 1.0
    return sign * axis, f"{joint.name}'s axis, pointing away from the joint before it"


def _orientation(x_axis: np.ndarray) -> tuple[float, float, float, float]:
    y_axis = np.eye(3)[int(np.argmin(np.abs(x_axis)))]
    y_axis = y_axis - (y_axis @ x_axis) * x_axis
    y_axis /= np.linalg.norm(y_axis)
    matrix = np.eye(4)
    matrix[:3, :3] = np.column_stack((x_axis, y_axis, np.cross(x_axis, y_axis)))
    return Pose.from_matrix(matrix).orientation


def tip_frame(tree: ModelTree, hand: Hand, arm: str) -> ToolFrame:
    """A frame to add on the tip of ``hand`` (fixed to its wrist link), x = approach."""
    approach, why = approach_of(tree, hand)
    reach = _tip(_shapes(tree, hand), approach)  # never behind the wrist's frame: a mount
    centre = reach * approach
    spec = FrameSpec(
        f"{arm}_standard_tool_frame",
        hand.end_effector_link,
        Pose((float(centre[0]), float(centre[1]), float(centre[2])), _orientation(approach)),
    )
    text = f"on the hand's tip, {round(reach, 3) + 0.0:.3f} m out of the wrist; approach: {why}"
    return ToolFrame(spec.name, spec, text)

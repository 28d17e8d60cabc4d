"""Stand-in boxes keep out of the space a gripper closes on.

A link whose mesh is missing gets a box spanning its joints (:mod:`stand_in_size`). At a
hand that box fills the space between the fingers: the drafted Fetch's tool frame is its
``gripper_link``, whose box (and its wrist's, which spans to it) sat where every grasp
puts the object, so the palm met every mug and drawer handle. A gripper that opens ``w``
wide takes objects ``w`` wide centred on its tool frame, so nothing of the hand but its
fingers lies within ``w / 2`` of the tool frame along the approach: a stand-in box of a
link fixed to the tool frame is cut back to end there (dropped if nothing is left). The
fingers close until they meet: a finger's stand-in box, a small cube at its joint, is
grown across to the tool frame's middle plane with the gripper closed (the Fetch's cubes
stopped 11 mm apart and closed on nothing over a bowl's rim); a five-fingered hand's are
not: its fingers curl side by side round what its palm holds (``grasping/palm.py``), and
Armar6's, grown to a middle plane lying on their row, met the mug before its palm did.
Real meshes and primitives a URDF gives are never changed.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

import numpy as np

from robocram.robots.description import ArmDescription
from robocram.robots.model_pose import link_pose, link_poses
from robocram.robots.robot_model import RobotModel
from robocram.robots.stand_in_size import is_stand_in
from robocram.robots.urdf_elements import Geometry, Link
from robocram.tf import Pose

ALIGNED = 0.999  # |cos| between the approach and a box axis for the box to be cut
CUT_TOLERANCE = 1e-9  # [m]
MANY_FINGERS = 5  # a hand of five fingers curls them side by side round what its palm
# holds: none is grown to the middle plane, which a parallel gripper's jaws close on and
# which lies on its finger row (Armar6's grown stand-in fingers met the mug first; a
# four-linked parallel gripper, Tracy's, still has its fingers grown)


def clear_grasp_space(model: RobotModel, arms: Mapping[str, ArmDescription]) -> RobotModel:
    """``model`` with the stand-in boxes of each gripper's rigid hand cut back behind its
    tool frame by half the widest opening; ``model`` itself when no box was cut.

    The result is kept with ``model`` (``RobotModel.derived``), so loading a description
    again shares one model and what is derived from it (its kinematics)."""
    key = tuple(sorted((name, _hand_key(arm)) for name, arm in arms.items()))
    kept = model.derived(_cut_models)
    if key not in kept:
        cut = _cleared(model, arms)
        if cut is not model:
            cut.derived(CutFrom).source = model
        kept[key] = cut
    return kept[key]


class CutFrom:
    """The model a cut model was cut from, held by the cut one: a description holds only
    the cut model, and the model memo holds the parse only weakly, so without this each
    load of the file would parse it and cut it again."""

    def __init__(self, cut: RobotModel) -> None:
        self.source: RobotModel | None = None


HandKey = tuple[object, ...]


def _hand_key(arm: ArmDescription) -> HandKey:
    """What of ``arm`` the cut reads."""
    gripper = arm.gripper
    closed = tuple(sorted(gripper.at(0.0).items())) if gripper is not None else ()
    opening = gripper.max_opening if gripper is not None else None
    return (arm.tool_frame, arm.end_effector_link, tuple(arm.gripper_links), closed, opening)


def _cut_models(model: RobotModel) -> dict[tuple[tuple[str, HandKey], ...], RobotModel]:
    """The models cut from ``model``, by the hands they were cut for (kept with it)."""
    return {}


def _cleared(model: RobotModel, arms: Mapping[str, ArmDescription]) -> RobotModel:
    links = dict(model.links)
    for arm in arms.values():
        gripper = arm.gripper
        opening = gripper.max_opening if gripper is not None else None
        if gripper is None or not opening or arm.tool_frame not in model.links:
            continue
        tool = link_pose(model, arm.tool_frame)
        approach = _approach(model, arm, tool)
        if approach is None:
            continue
        fingers = set(arm.gripper_links)
        rigid = [name for name in _rigid_with(model, arm.tool_frame) if name not in fingers]
        at_rest = link_poses(model, rigid)
        for name in rigid:
            links[name] = _cut(links[name], at_rest[name], tool, approach, opening)
        moved = fingers if _finger_count(model, fingers) < MANY_FINGERS else set()
        closed = link_poses(model, [arm.tool_frame, *moved], gripper.at(0.0))
        for name in moved:
            tip = _sliding_tip(model, name)
            links[name] = _to_middle(
                links[name], closed[name], closed[arm.tool_frame], approach, tip
            )
    if all(links[name] is model.links[name] for name in links):
        return model
    return RobotModel(model.name, links, model.joints, model.source)


def _finger_count(model: RobotModel, fingers: set[str]) -> int:
    """How many fingers ``fingers`` make: the links whose parent is no finger."""
    return sum(1 for j in model.joints.values() if j.child in fingers and j.parent not in fingers)


def _sliding_tip(model: RobotModel, link: str) -> bool:
    """Whether ``link`` is a parallel gripper's fingertip: a leaf (no joint sizes its box
    along the approach) that a prismatic joint moves, so it keeps its orientation and its
    body runs along the approach to where the fingers hold."""
    if any(joint.parent == link for joint in model.joints.values()):
        return False
    joint = model.parent_joint(link)
    while joint is not None and not joint.movable:
        joint = model.parent_joint(joint.parent)
    return joint is not None and joint.type == "prismatic"


def _approach(model: RobotModel, arm: ArmDescription, tool: Pose) -> np.ndarray | None:
    """The unit approach axis (root frame): from the wrist to the tool frame."""
    wrist = link_pose(model, arm.end_effector_link).position
    axis = np.subtract(tool.position, wrist)
    norm = float(np.linalg.norm(axis))
    return axis / norm if norm > 1e-6 else None


def _rigid_with(model: RobotModel, link: str) -> list[str]:
    """The links joined to ``link`` by fixed joints only (``link`` included)."""
    found, queue = {link}, [link]
    while queue:
        here = queue.pop()
        for joint in model.joints.values():
            if joint.type != "fixed" or here not in (joint.parent, joint.child):
                continue
            other = joint.child if here == joint.parent else joint.parent
            if other not in found:
                found.add(other)
                queue.append(other)
    return sorted(found)


def _cut(link: Link, at: Pose, tool: Pose, approach: np.ndarray, opening: float) -> Link:
    """``link`` (posed ``at`` in the root frame) with its stand-in boxes ended ``opening / 2``
    behind ``tool`` along ``approach``."""
    limit = float(np.dot(tool.position, approach)) - opening / 2  # along the approach, root
    collisions = tuple(
        replace(c, geometry=geometry, origin=origin)
        for c in link.collisions
        for geometry, origin in _cut_box(c.geometry, c.origin, at, approach, limit)
    )
    visuals = tuple(
        replace(v, geometry=geometry, origin=origin)
        for v in link.visuals
        for geometry, origin in _cut_box(v.geometry, v.origin, at, approach, limit)
    )
    if collisions == link.collisions and visuals == link.visuals:
        return link
    return Link(link.name, visuals, collisions, link.inertial)


def _cut_box(
    geometry: Geometry, origin: Pose, at: Pose, approach: np.ndarray, limit: float
) -> list[tuple[Geometry, Pose]]:
    """The shape once cut at ``limit`` (along ``approach``, root frame): unchanged when it is
    no stand-in box, lies short of the limit or turned across the approach; none when all
    of it lies beyond."""
    if not is_stand_in(geometry):
        return [(geometry, origin)]
    box = at * origin
    along = box.matrix()[:3, :3].T @ approach  # the approach in the box's own axes
    axis = int(np.argmax(np.abs(along)))
    if abs(float(along[axis])) < ALIGNED:
        return [(geometry, origin)]
    centre, half = float(np.dot(box.position, approach)), geometry.size[axis] / 2
    if centre + half <= limit + CUT_TOLERANCE:  # cut already (a description loaded again)
        return [(geometry, origin)]
    if centre - half >= limit:
        return []
    size = list(geometry.size)
    size[axis] = limit - (centre - half)
    shift = [0.0, 0.0, 0.0]
    shift[axis] = -float(np.sign(along[axis])) * (centre + half - limit) / 2
    moved = origin * Pose((shift[0], shift[1], shift[2]))
    return [(replace(geometry, size=(size[0], size[1], size[2])), moved)]


def _to_middle(link: Link, at: Pose, tool: Pose, approach: np.ndarray, tip: bool) -> Link:
    """Finger ``link`` (posed ``at``, gripper closed) with its stand-in boxes grown across
    to the plane through ``tool`` that splits the fingers, and, a parallel gripper's
    fingertip (``tip``), out along the approach to ``tool`` where they end short of it."""

    def grown(geometry: Geometry, origin: Pose) -> tuple[Geometry, Pose]:
        geometry, origin = _grown(geometry, origin, at, tool, approach)
        return _reaching(geometry, origin, at, tool, approach) if tip else (geometry, origin)

    collisions = tuple(
        replace(c, geometry=g, origin=o)
        for c in link.collisions
        for g, o in [grown(c.geometry, c.origin)]
    )
    visuals = tuple(
        replace(v, geometry=g, origin=o)
        for v in link.visuals
        for g, o in [grown(v.geometry, v.origin)]
    )
    if collisions == link.collisions and visuals == link.visuals:
        return link
    return Link(link.name, visuals, collisions, link.inertial)


def _grown(
    geometry: Geometry, origin: Pose, at: Pose, tool: Pose, approach: np.ndarray
) -> tuple[Geometry, Pose]:
    """A finger's stand-in box grown towards the middle plane until its inner face lies on
    it; any other shape, or a box that reaches it, unchanged."""
    if not is_stand_in(geometry):
        return geometry, origin
    box = at * origin
    offset = np.subtract(box.position, tool.position)
    across = offset - float(np.dot(offset, approach)) * approach  # from the middle, out
    rotation = box.matrix()[:3, :3]
    along = rotation.T @ across  # in the box's own axes
    axis = int(np.argmax(np.abs(along)))
    gap = abs(float(along[axis])) - geometry.size[axis] / 2  # inner face to the middle
    if gap <= CUT_TOLERANCE or np.linalg.norm(across) < CUT_TOLERANCE:
        return geometry, origin
    size = list(geometry.size)
    size[axis] += gap
    shift = [0.0, 0.0, 0.0]
    shift[axis] = -float(np.sign(along[axis])) * gap / 2
    moved = origin * Pose((shift[0], shift[1], shift[2]))
    return replace(geometry, size=(size[0], size[1], size[2])), moved


def _reaching(
    geometry: Geometry, origin: Pose, at: Pose, tool: Pose, approach: np.ndarray
) -> tuple[Geometry, Pose]:
    """A parallel gripper's fingertip's stand-in box grown out along the approach until it
    reaches ``tool``: a leaf has no joint to size it by (the box is a cube at its root),
    and the tool frame is where the fingers hold (the Donbot's WSG 50: cubes 23 mm past
    the guides, the tool frame 144 mm out, so the fingers closed under every mug). Any
    other shape, a box turned across the approach or one that reaches it, unchanged."""
    if not is_stand_in(geometry):
        return geometry, origin
    box = at * origin
    along = box.matrix()[:3, :3].T @ approach  # the approach in the box's own axes
    axis = int(np.argmax(np.abs(along)))
    if abs(float(along[axis])) < ALIGNED:
        return geometry, origin
    end = float(np.dot(box.position, approach)) + geometry.size[axis] / 2
    gap = float(np.dot(tool.position, approach)) - end
    if gap <= CUT_TOLERANCE:
        return geometry, origin
    size = list(geometry.size)
    size[axis] += gap
    shift = [0.0, 0.0, 0.0]
    shift[axis] = float(np.sign(along[axis])) * gap / 2
    moved = origin * Pose((shift[0], shift[1], shift[2]))
    return replace(geometry, size=(size[0], size[1], size[2])), moved

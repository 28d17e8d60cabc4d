"""How big a box stands in for a link whose mesh is missing: from the kinematics.

A link's body joins its own frame (where its parent joint turns it) to the joints of its
children, so the box spans those points, as thick as a fraction of the link's length in
the chain (a palm is thinner than an upper arm). A child that slides (a prismatic joint)
counts where its travel comes nearest the link's frame, if nearer than its origin: the
link's body ends where the child's begins at that end of the travel, so lowering a torso
does not sink it into a box of the column below (Armar6's platform reached its neck).
A child with no body (a frame: no shape on it or below it) is left out of the span when
a child with a body is there: Armar6's palm box reached its tool frame 7 cm before the
palm, where a held thing lies (a head whose children are all camera frames still spans
them). A palm, a finger row and a thumb (each a chain of links: a base's row of wheels is
none), is a plate (``robots/stand_in_palm.py``).
Placeholder inertias (``ixx = 1``) gave boxes of several metres that made every check fail
far from the cause; nothing here reads the inertia, and no box is longer than the robot's
own span.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from robocram.robots.stand_in_palm import palm_plate
from robocram.robots.urdf_elements import Geometry, Joint
from robocram.tf import Pose

THICKNESS_SHARE = 0.25  # of the link's length in the chain: the box's thickness
MIN_THICKNESS = 0.02  # [m]
MAX_THICKNESS = 0.08  # [m] an arm link; the base is allowed its children's span
LONE_THICKNESS = 0.04  # [m] a link with no offset anywhere near it (a frame on a frame)


@dataclass(frozen=True)
class StandInBox:
    """A stand-in box: its centre in the link frame and its extents [m]."""

    centre: Pose
    size: tuple[float, float, float]

    def geometry(self, uri: str) -> Geometry:
        """The box, marked (``filename``) with the mesh it stands in for."""
        return Geometry("box", size=self.size, filename=uri)


def is_stand_in(geometry: Geometry) -> bool:
    """Whether ``geometry`` is a box standing in for a missing mesh (see :class:`StandInBox`)."""
    return geometry.kind == "box" and bool(geometry.filename)


def stand_in_boxes(
    joints: Mapping[str, Joint], bodied: Collection[str] | None = None
) -> dict[str, StandInBox]:
    """Per link named by a joint: the box that stands in for its missing mesh. ``bodied``:
    the links with a shape (None: every link), so frames are told from bodies."""
    children: dict[str, list[Joint]] = {}
    parent_of: dict[str, Joint] = {}
    for joint in joints.values():
        children.setdefault(joint.parent, []).append(joint)
        parent_of[joint.child] = joint
    spanned = children if bodied is None else _without_frames(children, set(bodied))
    span = _span(joints, parent_of)
    boxes: dict[str, StandInBox] = {}
    for link in {*children, *parent_of}:
        length = _length(link, parent_of, children)  # a tool frame tells a hand's scale too
        thickness = min(max(THICKNESS_SHARE * length, MIN_THICKNESS), MAX_THICKNESS)
        if length <= 0.0:
            thickness = LONE_THICKNESS
        bases = [_nearest(j) for j in spanned.get(link, [])]
        fingers = all(j.child in children for j in spanned.get(link, []))  # chains, no wheels
        plate = palm_plate(bases) if fingers else None
        if plate is not None:
            boxes[link] = _plate_box(plate.points, plate.axes, thickness, span)
            continue
        points = [(0.0, 0.0, 0.0), *bases]
        low = [min(p[i] for p in points) for i in range(3)]
        high = [max(p[i] for p in points) for i in range(3)]
        size = tuple(min(high[i] - low[i] + thickness, span) for i in range(3))
        centre = Pose(tuple((low[i] + high[i]) / 2 for i in range(3)))  # type: ignore[arg-type]
        boxes[link] = StandInBox(centre, size)  # type: ignore[arg-type]
    return boxes


def _without_frames(
    children: Mapping[str, list[Joint]], bodied: set[str]
) -> dict[str, list[Joint]]:
    """``children`` less the frames (no shape on the child or below it) of each link that
    has a child with a body; a link whose children are all frames keeps them."""

    def has_body(link: str, seen: frozenset[str] = frozenset()) -> bool:
        if link in bodied:
            return True
        below = [j.child for j in children.get(link, []) if j.child not in seen]
        return any(has_body(child, seen | {link}) for child in below)

    kept: dict[str, list[Joint]] = {}
    for link, joints in children.items():
        bodies = [j for j in joints if has_body(j.child)]
        kept[link] = bodies if bodies else list(joints)
    return kept


def _plate_box(
    points: Sequence[tuple[float, float, float]],
    axes: NDArray[np.float64],
    thickness: float,
    span: float,
) -> StandInBox:
    """The box spanning ``points`` [m, link frame] in the plate's ``axes`` (rows), as thick
    as ``thickness`` past them on every side, no longer than ``span``."""
    local = np.asarray(points, float) @ axes.T
    low, high = local.min(axis=0), local.max(axis=0)
    size = tuple(min(float(high[i] - low[i]) + thickness, span) for i in range(3))
    middle = axes.T @ ((low + high) / 2)
    frame = np.eye(4)
    frame[:3, :3] = axes.T
    frame[:3, 3] = middle
    return StandInBox(Pose.from_matrix(frame), size)  # type: ignore[arg-type]


def _length(
    link: str, parent_of: Mapping[str, Joint], children: Mapping[str, list[Joint]]
) -> float:
    """The link's length in the chain: its parent joint's offset, else its farthest child's."""
    parent = parent_of.get(link)
    offset = math.dist((0.0, 0.0, 0.0), parent.origin.position) if parent is not None else 0.0
    if offset > 0.0:
        return offset
    return max((math.dist((0.0, 0.0, 0.0), _nearest(j)) for j in children.get(link, [])),
               default=0.0)  # fmt: skip


def _nearest(joint: Joint) -> tuple[float, float, float]:
    """Where ``joint``'s child frame comes nearest its parent's frame [m, parent frame]: its
    origin, or for a prismatic joint with limits the nearest point of its travel and its
    origin (a box only ever shortens: fingers sliding across a palm leave it as it was)."""
    origin = joint.origin.position
    if joint.type != "prismatic" or joint.lower is None or joint.upper is None:
        return origin
    if not (math.isfinite(joint.lower) and math.isfinite(joint.upper)):
        return origin
    axis = joint.origin.matrix()[:3, :3] @ np.asarray(joint.axis, float)
    axis /= max(float(np.linalg.norm(axis)), 1e-12)
    low, high = min(joint.lower, 0.0), max(joint.upper, 0.0)
    along = min(max(-float(axis @ np.asarray(origin)), low), high)
    x, y, z = (float(v) for v in np.asarray(origin) + along * axis)
    return (x, y, z)


def _span(joints: Mapping[str, Joint], parent_of: Mapping[str, Joint]) -> float:
    """The robot's span [m]: the widest extent of its joints' positions at zero, at least
    :data:`MAX_THICKNESS` (a robot of one link)."""
    positions: list[tuple[float, ...]] = [(0.0, 0.0, 0.0)]
    for joint in joints.values():
        pose = joint.origin
        above = joint.parent
        for _ in range(len(joints)):  # a loop (refused by RobotModel afterwards) ends too
            parent = parent_of.get(above)
            if parent is None:
                break
            pose = parent.origin * pose
            above = parent.parent
        positions.append(pose.position)
    extents = [max(p[i] for p in positions) - min(p[i] for p in positions) for i in range(3)]
    return max(max(extents), MAX_THICKNESS)

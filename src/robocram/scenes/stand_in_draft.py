"""Draft stand-ins for links whose mesh files are missing, from what the URDF does tell.

- **A drawer** (the moving link of a prismatic joint) becomes an open box. Its front is
  just behind the handle and its top a little above it; it is as deep as the joint
  travels (plus :data:`DEPTH_EXTRA`), as wide as the spacing to the next drawer beside it
  and as high as the spacing to the next one below, both capped.
- **A table or a counter top** (a link that never moves, named like one) becomes a table
  (a top on legs) standing on the floor when its frame is low, else a thin top at its
  frame (a worktop), as wide as the links standing on it reach. Its size is a guess, a
  doubt.

Each stand-in comes with why it was chosen; a guessed size, with a doubt too.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from robocram.scenes.environment_model import EnvironmentModel, EnvJoint
from robocram.scenes.stand_in import StandIn
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat

FRONT_GAP = 0.03  # [m] a handle sticks out this far in front of its drawer
TOP_ABOVE_HANDLE = 0.04  # [m] a drawer's rim above its handle
DEPTH_EXTRA = 0.05  # [m] a drawer is this much deeper than it travels
DRAWER_WIDTH = (0.2, 0.5, 0.8)  # [m] least, without neighbours, most
DRAWER_HEIGHT = (0.05, 0.12)  # [m] least, most (low walls let a hand in)
SPACING_GAP = 0.03  # [m] kept between neighbouring stand-ins
LINED_UP = 0.15  # [m] fronts this close along the way out are in one row
SAME_LEVEL = 0.1  # [m] handles this close in height (or sideways) are beside (or above)
TOP_NAMES = re.compile(r"table|counter|desk|worktop", re.IGNORECASE)
FLOOR_STANDING = 0.35  # [m] a top's frame lower than this is a table's foot: it stands
TABLE = (1.2, 0.8, 0.75)  # [m] a guessed table when nothing says its size
TOP_THICKNESS = 0.04  # [m] of a worktop stand-in
TOP_REACH = 0.3  # [m] a worktop reaches this far past the links standing on it


@dataclass(frozen=True)
class DraftedStandIn:
    """A stand-in, why it has that shape, and the doubt left (or None)."""

    stand_in: StandIn
    why: str
    doubt: str | None = None


@dataclass(frozen=True)
class DrawerFront:
    """Where a drawer's handle is [m] and which way it opens (a unit vector), in the root."""

    joint: EnvJoint
    handle: str
    at: Vector3
    out: Vector3


def drawer_fronts(
    model: EnvironmentModel, drawers: Iterable[tuple[EnvJoint, str]]
) -> list[DrawerFront]:
    """The front of each ``(joint, handle)`` drawer."""
    fronts = []
    for joint, handle in drawers:
        pose = model.pose(joint.child)
        out = quat.rotate(pose.orientation, _out_in_link(joint))
        fronts.append(DrawerFront(joint, handle, model.pose(handle).position, out))
    return fronts


def draft_stand_ins(model: EnvironmentModel, fronts: list[DrawerFront]) -> Iterator[DraftedStandIn]:
    """A stand-in for each drawer and each table or counter top whose meshes are missing."""
    for front in fronts:
        if _unshaped(model, front.joint.child):
            drafted = _drawer(model, front, fronts)
            if drafted is not None:
                yield drafted
    for link in model.boxes:
        if _unshaped(model, link) and TOP_NAMES.search(link) and not model.moved_by_joint(link):
            drafted = _top(model, link)
            if drafted is not None:
                yield drafted


def _unshaped(model: EnvironmentModel, link: str) -> bool:
    return link in model.unfound and not model.boxes.get(link)


def _out_in_link(joint: EnvJoint) -> Vector3:
    far = joint.upper if abs(joint.upper) >= abs(joint.lower) else joint.lower
    sign = math.copysign(1.0, far)
    ax, ay, az = joint.axis
    return (ax * sign, ay * sign, az * sign)


def _dot(a: Vector3, b: Vector3) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _axis_index(v: Vector3) -> int | None:
    """Which of the frame's axes ``v`` lies along, if any."""
    index = max(range(3), key=lambda i: abs(v[i]))
    return index if abs(v[index]) > 0.99 else None


def _spacings(front: DrawerFront, fronts: list[DrawerFront]) -> tuple[list[float], list[float]]:
    """Distances [m] to the drawers in the same row beside it and above or below it."""
    up = (0.0, 0.0, 1.0)
    side = (-front.out[1], front.out[0], 0.0)
    beside, stacked = [], []
    for other in fronts:
        if other is front or _dot(other.out, front.out) < 0.99:
            continue
        d = (other.at[0] - front.at[0], other.at[1] - front.at[1], other.at[2] - front.at[2])
        if abs(_dot(d, front.out)) > LINED_UP:
            continue
        sideways, height = abs(_dot(d, side)), abs(_dot(d, up))
        if height < SAME_LEVEL and sideways > SAME_LEVEL / 2:
            beside.append(sideways)
        elif sideways < SAME_LEVEL and height > SPACING_GAP:
            stacked.append(height)
    return beside, stacked


def _drawer(
    model: EnvironmentModel, front: DrawerFront, fronts: list[DrawerFront]
) -> DraftedStandIn | None:
    joint = front.joint
    pose = model.pose(joint.child)
    out = _out_in_link(joint)
    up = quat.rotate(quat.conjugate(pose.orientation), (0.0, 0.0, 1.0))
    out_axis = _axis_index(out)
    if up[2] < 0.99 or out_axis is None or out_axis == 2:
        return None  # a tilted drawer: its shape is left to the user (a mesh doubt)
    side_axis = 1 - out_axis
    beside, stacked = _spacings(front, fronts)
    low, default, high = DRAWER_WIDTH
    width = max(low, min(high, min(beside) - SPACING_GAP)) if beside else default
    height = max(DRAWER_HEIGHT[0], min(DRAWER_HEIGHT[1], min(stacked, default=1.0) - SPACING_GAP))
    depth = joint.upper - joint.lower + DEPTH_EXTRA
    if front.handle != joint.child:
        handle = (pose.inverse() * Pose(front.at)).position
        rim, top = _dot(handle, out) - FRONT_GAP, handle[2] + TOP_ABOVE_HANDLE
        side = handle[side_axis]
    else:
        rim, top, side = depth / 2, height / 2, 0.0
    centre = [0.0, 0.0, top - height / 2]
    centre[out_axis] = out[out_axis] * (rim - depth / 2)
    centre[side_axis] = side
    size = [0.0, 0.0, height]
    size[out_axis], size[side_axis] = depth, width
    wide = "the spacing beside it" if beside else "no drawer beside it"
    why = (
        f"{joint.name} travels {joint.upper - joint.lower:.2f} m: an open box "
        f"{depth:.2f} deep, {width:.2f} wide ({wide}), {height:.2f} high, behind its handle"
    )
    stand_in = StandIn(joint.child, "open_box", _rounded(size), _rounded(centre))
    return DraftedStandIn(stand_in, why)


def _top(model: EnvironmentModel, link: str) -> DraftedStandIn | None:
    pose = model.pose(link)
    up = quat.rotate(quat.conjugate(pose.orientation), (0.0, 0.0, 1.0))
    if up[2] < 0.99:
        return None
    z = pose.position[2]
    if z < FLOOR_STANDING:
        sx, sy, sz = TABLE
        stand_in = StandIn(link, "table", (sx, sy, sz), (0.0, 0.0, round(sz / 2 - z, 4)))
        why = f"named like a table, its frame {z:.2f} m up: a table standing on the floor"
        doubt = (
            f"{link}: its size is in a missing mesh; a {sx} x {sy} x {sz} m table is a guess: "
            "measure it, fix the StandIn's size and centre and the surface's height"
        )
        return DraftedStandIn(stand_in, why, doubt)
    xs = [abs(j.origin.position[0]) for j in model.children(link)]
    ys = [abs(j.origin.position[1]) for j in model.children(link)]
    sx = 2 * (max(xs, default=0.0) + TOP_REACH)
    sy = 2 * (max(ys, default=0.0) + TOP_REACH)
    stand_in = StandIn(link, "box", _rounded((sx, sy, TOP_THICKNESS)), (0.0, 0.0, 0.0))
    what = "the links on it" if xs else "nothing on it"
    why = f"named like a top, its frame {z:.2f} m up: a {TOP_THICKNESS} m top reaching past {what}"
    doubt = f"{link}: its outline is in a missing mesh; {sx:.2f} x {sy:.2f} m is a guess"
    return DraftedStandIn(stand_in, why, doubt)


def _rounded(v: Iterable[float]) -> Vector3:
    x, y, z = (round(c, 4) for c in v)
    return (x, y, z)

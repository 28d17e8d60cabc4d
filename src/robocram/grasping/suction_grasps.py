"""Grasps of a suction hand: the tool frame onto a face, no fingers, no opening.

A suction-like hand (``GripperDescription.suction()``) holds what its tool frame touches,
so a grasp puts the tool frame on the object's surface:

- ``top``: on the top face over the body's axis (a mug's handle is left aside), pointing
  down;
- ``rim`` (a hollow object, ``object_wall/2``): on the rim, over the middle of the wall,
  one place per side the box shows no handle; a hollow object's top face is its opening;
- ``side``: on a side face at half height, one place per side the box shows no handle,
  coming in level; lifted :data:`SIDE_LIFT` while drawn :data:`SIDE_LIFT_BACK` back along
  the approach (straight up, the Ridgeback's UR5 over a counter met its top with its
  forearm 72 mm deep at best; drawn back 0.10 m and lifted 0.05 m, it clears it by 21 mm).
  Tried after the others (``GRASP_NAMES``' order): a
  hand that reaches down onto the top keeps doing so, and one that cannot reach as far
  down over a counter takes the nearer side (the Ridgeback's UR5: 0.59 m from its base
  pointing down, the mug 0.61 m or more away).

The tool goes to the top of the object's box, which PyBullet's collision margin widens
1-2 mm past the shape: the hand touches the face within the 5 mm a suction hand holds by
(``projection/suction.py``), and a hand whose parts reach past its tool frame (fixed
fingers) goes no deeper into the object than that; a side grasp's to the box's side,
which a round body touches on the approach's line. Four turns about the approach each,
for the arm to choose from.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence

from robocram.grasping.errors import ObjectUntouchable
from robocram.grasping.grasp import Grasp
from robocram.grasping.hand import Hand, tool_orientation
from robocram.grasping.object_shape import ObjectShape
from robocram.tf import Pose, Vector3

PRE_GRASP = 0.10  # [m] the tool starts this far back along the approach (above, from the top)
LIFT = 0.10  # [m] the object is lifted this far
SIDE_LIFT = 0.05  # [m] a side touch lifts the object this far
SIDE_LIFT_BACK = 0.10  # [m] while drawing it this far back along the approach
HANDLE_MARGIN = 0.005  # [m] the box sticking out this far past the body is a handle
DOWN: Vector3 = (0.0, 0.0, -1.0)
TURNS = (0.0, math.pi, math.pi / 2, -math.pi / 2)
SIDES: tuple[Vector3, ...] = ((1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, 0.0))
SUCTION_NAMES = ("top", "rim", "side")


def _touch(hand: Hand, name: str, turn: float, at: Vector3) -> Grasp:
    """The tool at ``at`` pointing down, its opening axis turned ``turn`` about the vertical."""
    across: Vector3 = (round(math.cos(turn), 12), round(math.sin(turn), 12), 0.0)
    pose = Pose(at, tool_orientation(hand, DOWN, across))
    return Grasp(name, turn, pose, DOWN, PRE_GRASP, LIFT, 0.0, across)


def _top(shape: ObjectShape, hand: Hand) -> Iterator[Grasp]:
    if shape.wall is not None:
        return  # hollow: the top is an opening
    cx, cy = shape.centre
    for turn in TURNS:
        yield _touch(hand, "top", turn, (cx, cy, shape.high[2]))


def _rim(shape: ObjectShape, hand: Hand) -> Iterator[Grasp]:
    if shape.wall is None:
        return
    cx, cy = shape.centre
    d = shape.radius - shape.wall / 2
    for side in SIDES:
        if shape.reach(side) > shape.radius + HANDLE_MARGIN:
            continue  # a handle on this side
        at = (cx + side[0] * d, cy + side[1] * d, shape.high[2])
        for turn in TURNS:
            yield _touch(hand, "rim", turn, at)


def _side(shape: ObjectShape, hand: Hand) -> Iterator[Grasp]:
    """The tool on each side face without a handle, at half height, coming in level."""
    cx, cy = shape.centre
    z = shape.low[2] + shape.size[2] / 2
    for side in SIDES:
        out = shape.reach(side)
        if out > shape.radius + HANDLE_MARGIN:
            continue  # a handle on this side
        at = (cx + side[0] * out, cy + side[1] * out, z)
        approach: Vector3 = (-side[0], -side[1], 0.0)
        level: Vector3 = (-side[1], side[0], 0.0)
        for turn in TURNS:
            c, s = round(math.cos(turn), 12), round(math.sin(turn), 12)
            across: Vector3 = (c * level[0], c * level[1], s)  # level, then upright
            pose = Pose(at, tool_orientation(hand, approach, across))
            yield Grasp(
                "side", turn, pose, approach, PRE_GRASP, SIDE_LIFT, 0.0, across,
                lift_back=SIDE_LIFT_BACK,
            )  # fmt: skip


def _of_name(shape: ObjectShape, hand: Hand, name: str) -> Iterator[Grasp]:
    if name == "top":
        return _top(shape, hand)
    if name == "rim":
        return _rim(shape, hand)
    return _side(shape, hand)


def touching_grasps(shape: ObjectShape, hand: Hand, names: Sequence[str]) -> list[Grasp]:
    """The grasps of ``shape`` a suction ``hand`` can take, in ``names``' order.

    Raises:
        ObjectUntouchable: ``names`` allows no ``top``, ``rim`` or ``side`` for this shape.
    """
    found = [g for name in names if name in SUCTION_NAMES for g in _of_name(shape, hand, name)]
    if not found:
        raise ObjectUntouchable(shape.name, tuple(names))
    return found

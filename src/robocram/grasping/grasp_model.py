"""The grasp model: every grasp of an object a hand can take, from geometry alone.

Grasps (CRAM's names), in the object's frame (x forward, z up):

- ``top``: from above, over the body's axis, centred on the span the hand closes across
  (a handle widens it); the fingertips go :data:`TOP_STRADDLE` (or
  the hand's finger depth, if less) below the top, but no lower than half the height.
  Four turns: the opening along the object's x (width: its x size) or y.
- ``front``, ``left``, ``right``: sideways at half height, from the -x, +y and -y side
  (not through a handle); the opening is horizontal, the width the object's size across.
- ``rim`` (a hollow object, ``object_wall/2``): from above on the wall, the fingers
  straddling it ``RIM_DEPTH`` below the rim; one place per side the box shows no handle;
  a hand whose pads end behind its tool frame (``Hand.pads_behind`` at least
  :data:`PADS_BEHIND_DEEP`) again, deep (:data:`RIM_DEEP_FLOOR`), after all the others.
  Width: the wall's thickness. A palm hand lies flat over the rim, its wrist at the rim's
  height: its rim grasps come again tilted about the wall (:data:`RIM_TILTS`), the wrist
  raised, for a bowl down in a drawer; last of all, each whose hand, closing, goes below
  the object's bottom again raised until it keeps :data:`PALM_FLOOR` over it
  (:func:`_over_support`: Armar6's open thumb stood through the bowl's floor, its 11.6 cm
  fingers curled past the 6.4 cm bowl into the drawer's). A hand with fingers whose tips
  reach past its tool frame gets its flat rim grasps again last, raised until the tips
  keep over the object's floor (:func:`_fingers_over_floor`: TALOS's).
- ``handle`` (``object_handle/2``): sideways onto the bar that sticks out of the body,
  at half height; width: the bar's. A hand that fits no grasp round the body (top,
  front, left, right: a Panda's 80 mm against the mug's 88) also gets it from above, as
  a person with a small hand takes a mug: the fingers straddle the bar, the tool on its
  middle, then farther out. (Not by the rim: pybullet's mug collides as a closed
  cylinder, a finger inside its wall would be 2 cm in it; it has no ``object_wall``.)

Each needs its width plus :data:`CLEARANCE`; a grasp needing more than the hand opens is
not offered, and when none is left :class:`ObjectUngraspable` names both widths.

A suction hand (``Hand.suction``) closes on nothing: it touches. Its grasps put the tool
frame onto a face (``suction_grasps.py``): ``top`` on the top face over the body's axis,
``rim`` on a hollow object's rim, ``side`` on a side face at half height, coming in level
(last: a suction hand's only grasp from the side, where fingers have ``front``, ``left``
and ``right``; a hand with fingers has none of that name); it needs no opening.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import replace

import numpy as np

from robocram.grasping.errors import ObjectUngraspable, UnknownGraspError
from robocram.grasping.grasp import Grasp
from robocram.grasping.hand import Hand, tool_orientation
from robocram.grasping.object_shape import ObjectShape
from robocram.grasping.palm import Palm
from robocram.grasping.suction_grasps import touching_grasps
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
from robocram.tf.quaternion import Quaternion

GRASP_NAMES = ("top", "front", "left", "right", "rim", "handle", "side")
BODY_GRASPS = ("top", "front", "left", "right")  # around the body: a hand as wide as it
CLEARANCE = 0.002  # [m] added to an object's width: the hand must open this much wider
TOP_STRADDLE = 0.04  # [m] a top grasp's fingertips go at most this far below the top: a
# hand is as wide as its open tips only near them (the PR2's finger links behind the tips
# went 6.5 mm into a mug's wall 56 mm down, 5 cm over its bottom; at 40 mm they clear it by
# 0.7 mm, issue 35)
PALM_FLOOR = 0.01  # [m] a palm hand held sideways keeps this far over the object's bottom
RIM_DEPTH = 0.02  # [m] a rim grasp's tool frame below the rim
RIM_DEEP_FLOOR = 0.015  # [m] a deep rim grasp's tool frame over the object's bottom: tried
# after every other, for a hand whose pads end behind its tool frame (Tracy's Robotiq 85:
# its pads 18-36 mm behind it closed on nothing over the bowl's 6 cm wall)
PADS_BEHIND_DEEP = 0.01  # [m] a hand's pads end at least this far behind its tool frame:
# it gets deep rim grasps (Tracy's 18 mm; Boxy's 6 mm; the PR2's, HSR's and Fetch's reach
# past it: none, which left their plans as they were)
RIM_DEEPER_AT_LEAST = 0.01  # [m] deeper than the rim grasp by less: no deep one
RIM_TILTS = (0.3,)  # [rad] a palm hand's rim grasps tilted so (each after the flat ones)
PRE_GRASP = 0.10  # [m] the tool starts this far back along its approach
LIFT = 0.10  # [m] the object is lifted this far
HANDLE_MARGIN = 0.005  # [m] the box sticking out this far past the body is a handle
HANDLE_OUTWARD = (0.0, 0.015, 0.03)  # [m] a handle from above: the tool this far out past
# the bar's middle (the model knows no finger's breadth: the Z1's jaw is a plate 88 mm
# broad, which over the bar's middle goes 1 cm into the mug's body)
DOWN: Vector3 = (0.0, 0.0, -1.0)
SIDES: tuple[Vector3, ...] = ((1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, 0.0))


def _grasp(
    hand: Hand,
    name: str,
    turn: float,
    at: Vector3,
    approach: Vector3,
    opening: Vector3,
    width: float,
    shape: ObjectShape,
) -> Grasp:
    orientation = tool_orientation(hand, approach, opening)
    if hand.palm is not None:
        at = _palm_on_side(shape, at, approach, orientation, hand.palm, width / 2)
    pose = Pose(at, orientation)
    return Grasp(name, turn, pose, approach, PRE_GRASP, LIFT, width + CLEARANCE, opening)


def _palm_on_side(
    shape: ObjectShape,
    at: Vector3,
    approach: Vector3,
    orientation: Quaternion,
    palm: Palm,
    half_width: float,
) -> Vector3:
    """The tool frame's place that puts a palm hand's palm against the side of the object
    where the approach through ``at`` enters its box, holding a body ``half_width``
    across its fingers (:meth:`Palm.holding`); raised until the hand's lower
    end (its row standing up, in a grasp from the side) is :data:`PALM_FLOOR` over the
    object's bottom: the TIAGo's little finger went into the table."""
    offset = quat.rotate(orientation, _held(shape, at, approach, palm, half_width))
    rise = _palm_rise(shape, at, approach, orientation, palm, half_width)
    return (at[0] - offset[0], at[1] - offset[1], at[2] - offset[2] + rise)


def _held(
    shape: ObjectShape, at: Vector3, approach: Vector3, palm: Palm, half_width: float
) -> Vector3:
    """Where [m, tool frame] the palm hand holds the body entered at ``at``."""
    depth = sum(
        a * (p - low) if a > 0 else -a * (high - p)
        for a, p, low, high in zip(approach, at, shape.low, shape.high, strict=True)
    )
    return palm.holding(half_width, depth, flat=approach == DOWN)


def _palm_rise(
    shape: ObjectShape,
    at: Vector3,
    approach: Vector3,
    orientation: Quaternion,
    palm: Palm,
    half_width: float,
) -> float:
    """How far [m] the palm hand holding at ``at`` is raised to keep its lower end
    :data:`PALM_FLOOR` over the object's bottom (0 where it is already)."""
    offset = quat.rotate(orientation, _held(shape, at, approach, palm, half_width))
    knuckles = quat.rotate(orientation, palm.knuckles)
    across = quat.rotate(orientation, palm.across)
    lowest = at[2] - offset[2] + knuckles[2] + min(s * across[2] for s in palm.span)
    return max(0.0, shape.low[2] + PALM_FLOOR - lowest)


def _closes_over_top(
    hand: Hand, shape: ObjectShape, at: Vector3, approach: Vector3, opening: Vector3, width: float
) -> bool:
    """Whether a palm hand held sideways is raised so far (:func:`_palm_rise`) that the
    place it holds lies over the body's top: its fingers close on nothing. Rollin'
    Justin's open hand reaches 106 mm across its row on the thumb's side, 91 on the
    other: turned thumb down, its handle grasp rose 63 mm and held 10 mm over the 106 mm
    mug's top (the left hand closed on nothing); turned the other way, 48 mm (5 under)."""
    if hand.palm is None or approach[2] != 0.0:
        return False
    orientation = tool_orientation(hand, approach, opening)
    rise = _palm_rise(shape, at, approach, orientation, hand.palm, width / 2)
    return at[2] + rise > shape.high[2]


def _top(shape: ObjectShape, hand: Hand) -> Iterator[Grasp]:
    """Over the body's axis, the hand centred on the span it closes across: a mug's
    handle widens it to one side, and a hand over the body's axis met the handle with one
    finger 2 cm before the other finger met the body."""
    cx, cy = shape.centre
    sx, sy, height = shape.size
    mx, my = (shape.low[0] + shape.high[0]) / 2, (shape.low[1] + shape.high[1]) / 2
    z = max(shape.low[2] + height / 2, shape.high[2] - min(hand.finger_depth, TOP_STRADDLE))
    for turn in (0.0, math.pi, math.pi / 2, -math.pi / 2):
        opening = (round(math.cos(turn), 12), round(math.sin(turn), 12), 0.0)
        along_x = abs(opening[0]) > 0.5
        width = sx if along_x else sy
        at = (mx, cy, z) if along_x else (cx, my, z)
        yield _grasp(hand, "top", turn, at, DOWN, opening, width, shape)


def _side(shape: ObjectShape, hand: Hand, name: str) -> Iterator[Grasp]:
    facing = {"front": SIDES[1], "left": SIDES[2], "right": SIDES[3]}[name]
    if shape.handle is not None and shape.reach(facing) > shape.radius + HANDLE_MARGIN:
        return  # the hand would come in through the handle
    cx, cy = shape.centre
    sx, sy, height = shape.size
    z = shape.low[2] + height / 2
    if name == "front":
        approach: Vector3 = (1.0, 0.0, 0.0)
        at: Vector3 = (shape.low[0] + min(cx - shape.low[0], hand.finger_depth), cy, z)
        across, width = (0.0, 1.0, 0.0), sy
    else:
        sign = -1.0 if name == "left" else 1.0
        edge = shape.high[1] if name == "left" else shape.low[1]
        approach = (0.0, sign, 0.0)
        at = (cx, edge + sign * min(abs(edge - cy), hand.finger_depth), z)
        across, width = (1.0, 0.0, 0.0), sx
    for turn in (0.0, math.pi):
        opening = across if turn == 0.0 else (-across[0], -across[1], 0.0)
        if not _closes_over_top(hand, shape, at, approach, opening, width):
            yield _grasp(hand, name, turn, at, approach, opening, width, shape)


def _rim(shape: ObjectShape, hand: Hand) -> Iterator[Grasp]:
    """On the wall from above, one place per side without a handle; a palm hand's then
    again tilted (:data:`RIM_TILTS`, :func:`_tilted`); a hand whose pads end behind its
    tool frame's then again deep (:data:`RIM_DEEP_FLOOR`); a palm hand's, last, each
    again raised over the support (:func:`_over_support`); another hand's whose fingers
    reach past its tool frame, last, each again raised over the floor
    (:func:`_fingers_over_floor`)."""
    if shape.wall is None:
        return
    cx, cy = shape.centre
    r = shape.radius
    flat: list[tuple[Vector3, Grasp]] = []
    for side in SIDES:
        if shape.reach(side) > r + HANDLE_MARGIN:
            continue  # a handle on this side
        d = r - shape.wall / 2
        at = (cx + side[0] * d, cy + side[1] * d, shape.high[2] - RIM_DEPTH)
        for turn in (0.0, math.pi):
            opening = side if turn == 0.0 else (-side[0], -side[1], 0.0)
            flat.append((at, _grasp(hand, "rim", turn, at, DOWN, opening, shape.wall, shape)))
    yield from (grasp for _, grasp in flat)
    palm = hand.palm
    tilted = [] if palm is None else [_tilted(g, at, t, palm) for t in RIM_TILTS for at, g in flat]
    yield from tilted
    deeper = shape.high[2] - RIM_DEPTH - (shape.low[2] + RIM_DEEP_FLOOR)
    behind = hand.palm is None and hand.pads_behind >= PADS_BEHIND_DEEP
    if behind and deeper >= RIM_DEEPER_AT_LEAST:
        for at, grasp in flat:
            low = (at[0], at[1], at[2] - deeper)
            yield replace(grasp, tool=Pose(low, grasp.tool.orientation), deeper=deeper)
    if palm is not None:
        for grasp in [*(g for _, g in flat), *tilted]:
            raised = _over_support(grasp, palm, shape)
            if raised is not None:
                yield raised
    else:
        for _, grasp in flat:
            raised = _fingers_over_floor(grasp, hand, shape)
            if raised is not None:
                yield raised


def _fingers_over_floor(grasp: Grasp, hand: Hand, shape: ObjectShape) -> Grasp | None:
    """``grasp`` (a flat rim grasp, from above) raised until fingers that reach past the
    tool frame (``-hand.pads_behind``, the farthest over their stroke) keep
    :data:`PALM_FLOOR` over the object's floor, taken as thick as its wall; None when they
    keep over it as it is, or when raised so the tool frame would be over the rim. TALOS's
    curling fingers reach 42.8 mm past its tool frame: from 2 cm under a bowl's rim the
    inner one met the bowl's floor (2 mm under it open) while the outer two were still 29
    mm or more off the wall; 15 mm higher they close on the wall."""
    reach = -hand.pads_behind
    if reach <= 0.0 or shape.wall is None:
        return None
    x, y, z = grasp.tool.position
    floor = shape.low[2] + shape.wall + PALM_FLOOR
    rise = floor - (z - reach)
    if rise <= 0.0 or z + rise > shape.high[2]:
        return None
    return replace(grasp, tool=Pose((x, y, z + rise), grasp.tool.orientation), raised=rise)


def _over_support(grasp: Grasp, palm: Palm, shape: ObjectShape) -> Grasp | None:
    """``grasp`` raised until the hand, at every opening as it closes (:attr:`Palm.swept`,
    thumb too), keeps :data:`PALM_FLOOR` over the object's bottom; None when it keeps
    over the bottom as it is (it does not go into what the object stands on: the TIAGo's
    Hey5 keeps 4.6 mm over the bowl's, and its rim grasps stay as they are). Armar6's open
    thumb stood 10.5 cm out of its palm, through the bowl's floor, and its 11.6 cm fingers,
    curling round the wall of a bowl 6.4 cm tall, met the drawer's floor, 24 mm below the
    bowl's bottom, before the bowl: 34 mm higher (tilted) they close on the wall against
    the thumb."""
    if not len(palm.swept):
        return None
    up = grasp.tool.matrix()[2, :3]  # each tool axis's share of the object's z
    lowest = grasp.tool.position[2] + float((palm.swept @ up).min())
    if lowest >= shape.low[2]:
        return None
    rise = shape.low[2] + PALM_FLOOR - lowest
    x, y, z = grasp.tool.position
    return replace(grasp, tool=Pose((x, y, z + rise), grasp.tool.orientation), raised=rise)


def _tilted(grasp: Grasp, held: Vector3, tilt: float, palm: Palm) -> Grasp:
    """``grasp`` turned by ``tilt`` [rad] about the wall's tangent through ``held`` (the
    point its fingers hold), the way that raises the wrist. A palm hand lies flat over a
    rim with its wrist at the rim's height: the TIAGo's wrist housing met the bowl (6 mm)
    and its forearm the open drawer's front; tilted, both come from above, and the fingers
    still close on the wall (0.5 rad: they closed on nothing). The approach stays
    straight down."""
    q = grasp.tool.orientation
    wrist = quat.rotate(q, (-palm.along[0], -palm.along[1], -palm.along[2]))
    axis = (wrist[1], -wrist[0], 0.0)  # turning about wrist x up raises the wrist
    if math.hypot(axis[0], axis[1]) < 1e-9:
        return grasp
    turn = quat.from_axis_angle(axis, tilt)
    offset = np.subtract(grasp.tool.position, held)
    moved = np.add(held, quat.rotate(turn, (offset[0], offset[1], offset[2])))
    tool = Pose(
        (float(moved[0]), float(moved[1]), float(moved[2])), quat.normalized(quat.multiply(turn, q))
    )
    return replace(grasp, tool=tool, tilt=tilt)


def _handle_side(shape: ObjectShape) -> Vector3 | None:
    """The side the handle sticks out on (None: no handle, or the box shows none)."""
    if shape.handle is None:
        return None
    side = max(SIDES, key=lambda s: shape.reach(s))
    return side if shape.reach(side) > shape.radius + HANDLE_MARGIN else None


def _handle(shape: ObjectShape, hand: Hand) -> Iterator[Grasp]:
    side = _handle_side(shape)
    if side is None or shape.handle is None:
        return
    r = shape.radius
    out = shape.reach(side)
    cx, cy = shape.centre
    d = out - min((out - r) / 2, hand.finger_depth)
    at = (cx + side[0] * d, cy + side[1] * d, shape.low[2] + shape.size[2] / 2)
    approach = (-side[0], -side[1], 0.0)
    across = (-side[1], side[0], 0.0)
    for turn in (0.0, math.pi):
        opening = across if turn == 0.0 else (-across[0], -across[1], 0.0)
        if not _closes_over_top(hand, shape, at, approach, opening, shape.handle):
            yield _grasp(hand, "handle", turn, at, approach, opening, shape.handle, shape)


def _handle_from_above(shape: ObjectShape, hand: Hand) -> Iterator[Grasp]:
    """The handle taken from above, a small hand's grip: the fingers straddle its outer
    bar across its width, the tool frame on the bar's middle (a loop handle's middle, where
    the side grasp puts the tool, is its hole), :data:`TOP_STRADDLE` (or the finger depth)
    below the top; then the tool farther out by :data:`HANDLE_OUTWARD`, the bar nearer
    the fingers' inner edge, for fingers so broad that they would meet the body."""
    side = _handle_side(shape)
    if side is None or shape.handle is None:
        return
    cx, cy = shape.centre
    z = max(shape.low[2] + shape.size[2] / 2, shape.high[2] - min(hand.finger_depth, TOP_STRADDLE))
    across = (-side[1], side[0], 0.0)
    for out in HANDLE_OUTWARD:
        d = shape.reach(side) - shape.handle / 2 + out
        at = (cx + side[0] * d, cy + side[1] * d, z)
        for turn in (0.0, math.pi):
            opening = across if turn == 0.0 else (-across[0], -across[1], 0.0)
            grasp = _grasp(hand, "handle", turn, at, DOWN, opening, shape.handle, shape)
            if hand.palm is None or not _over_body(shape, grasp.tool, hand.palm):
                yield grasp


def _over_body(shape: ObjectShape, tool: Pose, palm: Palm) -> bool:
    """Whether the open palm hand at ``tool`` (object frame) lies over the body, below
    its top: closing, that finger or thumb meets the body before the others close round
    the handle (the TIAGo's Hey5 from above: its thumb across the mug 6.5 mm below the
    rim, or its little finger 4 mm into it, and it met the mug on one side only)."""
    if not len(palm.points):
        return False
    points = palm.points @ quat.to_matrix(tool.orientation).T + np.asarray(tool.position)
    cx, cy = shape.centre
    inside = np.hypot(points[:, 0] - cx, points[:, 1] - cy) < shape.radius
    return bool((inside & (points[:, 2] < shape.high[2])).any())


def _of_name(shape: ObjectShape, hand: Hand, name: str) -> Iterator[Grasp]:
    if name == "top":
        return _top(shape, hand)
    if name in ("front", "left", "right"):
        return _side(shape, hand, name)
    if name == "rim":
        return _rim(shape, hand)
    if name == "handle":
        return _handle(shape, hand)
    if name == "side":
        return iter(())  # a suction hand's touch (suction_grasps.py); fingers: front, left, right
    raise UnknownGraspError(name, GRASP_NAMES)


def grasps(shape: ObjectShape, hand: Hand, names: Sequence[str] = GRASP_NAMES) -> list[Grasp]:
    """The grasps of ``shape`` that ``hand`` opens wide enough for, in ``names``' order;
    when none round the body fits (or ``names`` allows none), the handle from above last.

    Raises:
        ObjectUngraspable: none of them fits the hand (the error names both widths).
        UnknownGraspError: a name is not one of :data:`GRASP_NAMES`.
    """
    if hand.suction:
        return touching_grasps(shape, hand, names)
    every = [g for name in names for g in _of_name(shape, hand, name)]
    widest = hand.max_opening if hand.palm is None else min(hand.max_opening, hand.palm.wraps)
    fitting = [g for g in every if g.opening <= widest]
    if "handle" in names and not any(g.name in BODY_GRASPS for g in fitting):
        fitting += [g for g in _handle_from_above(shape, hand) if g.opening <= widest]
    if not fitting:
        needed = min((g.opening for g in every), default=math.inf)
        raise ObjectUngraspable(shape.name, widest, needed)
    return fitting

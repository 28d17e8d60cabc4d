"""Putting a thing down upright that the hand holds askew.

A location for a held thing (``on``/``in_`` with ``for_``) keeps the orientation it has in
the hand and rests its lowest point on the surface. An arm parked to carry may hold it
tilted (a Boxy's parked hand holds a spoon taken from above 60 degrees askew): put down so,
it meets the surface before the hand is there, or falls over when let go. It goes down
upright instead, turned about the least axis, its lowest point where the spot has it.
"""

from __future__ import annotations

import itertools
import math

from robocram.knowledge.grasp_predicates import OBJECT_EXTENT
from robocram.logic import current_kb
from robocram.tf import Pose
from robocram.tf import quaternion as quat

LEVEL_TILT = math.radians(10.0)  # [rad] a thing held tilted more than this goes down upright
UPRIGHT_GAP = 0.005  # [m] put this much higher: the KB's box and the bounds the location's
# height came from are a few mm apart (a spoon put down level met the table 0.5 mm deep)


def _lowest(orientation: quat.Quaternion, low: tuple[float, ...], high: tuple[float, ...]) -> float:
    """The height [m] of the lowest corner of the box ``low``..``high`` turned so."""
    corners = itertools.product(*zip(low, high, strict=True))
    return min(quat.rotate(orientation, (c[0], c[1], c[2]))[2] for c in corners)


def upright_put(name: str, spot: Pose) -> Pose | None:
    """Where to put ``name`` upright at ``spot`` (its pose as a location gives it, turned
    as it was held, resting there); None when it is within :data:`LEVEL_TILT` of upright,
    upside down (no least axis), or the KB knows no box of it."""
    up = quat.rotate(spot.orientation, (0.0, 0.0, 1.0))
    tilt = math.acos(max(-1.0, min(1.0, up[2])))
    norm = math.hypot(up[0], up[1])
    if tilt <= LEVEL_TILT or norm < 1e-9:
        return None
    extent = OBJECT_EXTENT.first(current_kb(), object=name)
    if extent is None:
        return None
    turn = quat.from_axis_angle((up[1] / norm, -up[0] / norm, 0.0), tilt)
    levelled = quat.multiply(turn, spot.orientation)
    rise = _lowest(spot.orientation, extent.low, extent.high)
    rise -= _lowest(levelled, extent.low, extent.high)
    x, y, z = spot.position
    return Pose((x, y, z + rise + UPRIGHT_GAP), levelled)

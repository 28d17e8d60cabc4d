"""A palm's stand-in: a plate shaped from its finger row and its thumb, not a box over them.

A palm carries a row of fingers and a thumb set off from that row. A box spanning all
their joints fills the room before the palm where a held thing lies: Armar6's palm box
reached its thumb's base 4.7 cm off the palm, and the rim of the bowl the palm held was
28 mm inside it (5 mm allowed). The palm's body is the plate through the link's own frame
(the wrist) and the finger row; the thumb's base counts where it lies on that plate (the
thumb's own links reach out from it). A link whose children with a body each start a
chain of links (``stand_in_size.py`` asks) is a palm when at least
:data:`MIN_ROW_FINGERS` of its children with a body lie on a line (within
:data:`ROW_STRAIGHTNESS` of the row's length) and one more, the thumb, lies at least
:data:`THUMB_OFFSET` of that length off it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

MIN_ROW_FINGERS = 3  # two points always make a row: three fingers and a thumb at least
ROW_STRAIGHTNESS = 0.25  # a finger base this far (of the row's length) off the row: no row
THUMB_OFFSET = 0.5  # the thumb's base at least this far (of the row's length) off the row
MIN_ROW_LENGTH = 0.02  # [m] fingers closer together than this make no row
ALIGNED = 1.0 - 1e-9  # |cos| between the plate's normal and a link axis: the link's axes


@dataclass(frozen=True)
class PalmPlate:
    """Where a palm's plate lies, in the link frame: its axes (rows: two in the plate, then
    its normal) and the points it spans (the frame's origin, the finger bases, the thumb's
    base on the plate)."""

    axes: NDArray[np.float64]  # 3 x 3, rows
    points: tuple[tuple[float, float, float], ...]


def palm_plate(bases: Sequence[tuple[float, float, float]]) -> PalmPlate | None:
    """The plate of a palm whose children with a body start at ``bases`` [m, link frame];
    None when they are no finger row and thumb."""
    if len(bases) < MIN_ROW_FINGERS + 1:
        return None
    points = np.asarray(bases, float)
    found: tuple[float, int, NDArray[np.float64], NDArray[np.float64]] | None = None
    for thumb in range(len(points)):
        row = np.delete(points, thumb, axis=0)
        centre = row.mean(axis=0)
        direction = np.linalg.svd(row - centre)[2][0]
        along = (row - centre) @ direction
        length = float(along.max() - along.min())
        if length < MIN_ROW_LENGTH:
            continue
        off = float(np.linalg.norm(_across(row - centre, direction), axis=1).max())
        away = float(np.linalg.norm(_across(points[thumb] - centre, direction)))
        if off > ROW_STRAIGHTNESS * length or away < THUMB_OFFSET * length:
            continue
        if found is None or off / length < found[0]:
            found = (off / length, thumb, centre, direction)
    if found is None:
        return None
    _, thumb, centre, direction = found
    normal = _normal(direction, centre, points[thumb] - centre)
    axes = _plate_axes(normal)
    thumb_base = points[thumb] - float(normal @ points[thumb]) * normal  # onto the plate
    spanned = [np.zeros(3), *np.delete(points, thumb, axis=0), thumb_base]
    return PalmPlate(axes, tuple((float(p[0]), float(p[1]), float(p[2])) for p in spanned))


def _across(offsets: NDArray[np.float64], direction: NDArray[np.float64]) -> NDArray[np.float64]:
    """``offsets`` less their part along ``direction``."""
    return offsets - np.multiply.outer(offsets @ direction, direction)


def _normal(
    direction: NDArray[np.float64], centre: NDArray[np.float64], to_thumb: NDArray[np.float64]
) -> NDArray[np.float64]:
    """The plate's normal: across the row and the way from the link's frame to it (or, the
    frame on the row, the way to the thumb)."""
    inward = _across(centre, direction)
    if float(np.linalg.norm(inward)) < MIN_ROW_LENGTH / 2:
        inward = _across(to_thumb, direction)
    normal = np.cross(direction, inward)
    return normal / float(np.linalg.norm(normal))


def _plate_axes(normal: NDArray[np.float64]) -> NDArray[np.float64]:
    """Axes for the plate: the link axis lying most in the plate (projected onto it), the
    one across it in the plate, then ``normal``, so a plate in a link plane is a plain box."""
    eye = np.eye(3)
    if float(np.abs(normal).max()) >= ALIGNED:
        return eye
    first = eye[int(np.argmin(np.abs(eye @ normal)))]
    first = first - float(first @ normal) * normal
    first /= float(np.linalg.norm(first))
    second = np.cross(normal, first)
    return np.vstack([first, second, normal])

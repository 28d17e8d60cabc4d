"""The curves a tool point follows: lawn-mower lanes, a spiral, sawing strokes, a tilt.

Pure geometry in ``map`` (no robot, no world): each function gives the poses of a tool
point, from an approach above the work to a retreat above it, the tool's orientation
given. The plans of the tool actions send them as ``moving-tool-path`` (and ``pouring``,
``cutting``) motions; the process module follows them as checked, timed tool paths.
"""

from __future__ import annotations

import math

from robocram.tf import Pose, Quaternion, Vector3
from robocram.tf import quaternion as quat

APPROACH = 0.05  # [m] above the work where a path starts and ends


def _at(x: float, y: float, z: float, orientation: Quaternion) -> Pose:
    return Pose((x, y, z), orientation)


def lanes(
    region: Pose, size: tuple[float, float], footprint: tuple[float, float], overlap: float = 0.2
) -> list[tuple[float, float]]:
    """The lawn-mower (boustrophedon) lanes' turning points, in the region's frame: lanes
    along its x, ``footprint``'s y apart less ``overlap`` of it, so that a tool of that
    footprint covers the whole ``size`` [m] region (centre at ``region``)."""
    half = (max(size[0] - footprint[0], 0.0) / 2, max(size[1] - footprint[1], 0.0) / 2)
    spacing = footprint[1] * (1.0 - overlap)
    count = max(1, math.ceil(2 * half[1] / spacing) + 1) if half[1] > 0 else 1
    ys = [-half[1] + 2 * half[1] * k / (count - 1) for k in range(count)] if count > 1 else [0.0]
    points = []
    for k, y in enumerate(ys):
        xs = (-half[0], half[0]) if k % 2 == 0 else (half[0], -half[0])
        points += [(xs[0], y), (xs[1], y)]
    return points


def coverage_path(
    region: Pose,
    size: tuple[float, float],
    footprint: tuple[float, float],
    height: float,
    orientation: Quaternion,
) -> list[Pose]:
    """Tool point poses over the lanes of :func:`lanes`, at ``height`` [m, map] (the
    surface, less how far the tool presses), approached and left from above."""
    points = [region.transform_point((x, y, 0.0)) for x, y in lanes(region, size, footprint)]
    first, last = points[0], points[-1]
    return [
        _at(first[0], first[1], height + APPROACH, orientation),
        *(_at(p[0], p[1], height, orientation) for p in points),
        _at(last[0], last[1], height + APPROACH, orientation),
    ]


def spiral_path(
    centre: Vector3, radius: float, turns: float, orientation: Quaternion, step: float = 0.4
) -> list[Pose]:
    """An Archimedean spiral at ``centre`` (map; its height the tool point's) out to
    ``radius`` [m] in ``turns`` turns and back to the middle, ``step`` [rad] apart,
    entered and left from :data:`APPROACH` above the middle."""
    x, y, z = centre
    count = max(2, math.ceil(2 * math.pi * turns / step))
    out = []
    for k in range(count + 1):
        angle = 2 * math.pi * turns * k / count
        r = radius * k / count
        out.append(_at(x + r * math.cos(angle), y + r * math.sin(angle), z, orientation))
    back = [_at(p.position[0], p.position[1], z, orientation) for p in reversed(out[:-1])]
    above = _at(x, y, z + APPROACH, orientation)
    return [above, *out, *back, above]


def saw_path(
    cuts: list[Vector3],
    blade: Vector3,
    top: float,
    bottom: float,
    orientation: Quaternion,
    stroke: float = 0.015,
    strokes: int = 4,
) -> list[Pose]:
    """Sawing through each of ``cuts`` (points in map on the cut's plane, at the
    object's middle): from :data:`APPROACH` above ``top`` [m] down to ``bottom`` [m] in
    ``strokes`` back-and-forth strokes of ``stroke`` [m] along ``blade`` (a horizontal
    unit vector in map), and up again."""
    poses = []
    for cx, cy, _ in cuts:
        above = _at(cx, cy, top + APPROACH, orientation)
        poses.append(above)
        for k in range(1, 2 * strokes + 1):
            z = top - (top - bottom) * k / (2 * strokes)
            side = stroke if k % 2 else -stroke
            poses.append(_at(cx + side * blade[0], cy + side * blade[1], z, orientation))
        poses.append(_at(cx, cy, bottom, orientation))
        poses.append(above)
    return poses


def tilt_path(
    lip: Vector3,
    upright: Quaternion,
    toward: Vector3,
    angle: float,
    height: float,
    steps: int = 12,
) -> list[Pose]:
    """The lip of a vessel ``height`` [m] high going down to ``lip`` (map) while the
    vessel turns about the horizontal axis across ``toward`` (the unit vector from its
    axis to the lip) by up to ``angle`` [rad]: the lip is ``height * cos`` of the turn above
    ``lip`` (the vessel's bottom stays as high as the lip ends) until it lies level;
    entered from :data:`APPROACH` above that, upright."""
    axis = (-toward[1], toward[0], 0.0)  # z x toward: turning by +angle tips the lip down
    norm = math.hypot(axis[0], axis[1])
    axis = (axis[0] / norm, axis[1] / norm, 0.0)
    x, y, z = lip
    poses = [_at(x, y, z + height + APPROACH, upright), _at(x, y, z + height, upright)]
    for k in range(1, steps + 1):
        turn = angle * k / steps
        turned = quat.multiply(quat.from_axis_angle(axis, turn), upright)
        poses.append(_at(x, y, z + height * max(math.cos(turn), 0.0), turned))
    return poses

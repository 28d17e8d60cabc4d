"""How much of a region a wiping tool covered: the region as a grid of cells, each marked
when the tool's footprint was over it in contact with the surface."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from robocram.tf import Pose
from robocram.tf import quaternion as quat

CELL = 0.005  # [m] the grid's cell
IN_CONTACT = 0.001  # [m] the tool's underside this near the surface (or below) touches it


def covered_share(
    region: Pose,
    size: tuple[float, float],
    footprint: tuple[float, float],
    surface: float,
    poses: Sequence[Pose],
) -> float:
    """The share (0..1) of the ``size`` [m] region at ``region`` (map) whose cell centres
    came inside the tool's ``footprint`` (its underside's extents, turned with the tool's
    yaw) at one of ``poses`` (its underside's middle) at most :data:`IN_CONTACT` above the
    ``surface`` height [m]."""
    nx, ny = max(1, round(size[0] / CELL)), max(1, round(size[1] / CELL))
    xs = (np.arange(nx) + 0.5) * size[0] / nx - size[0] / 2
    ys = (np.arange(ny) + 0.5) * size[1] / ny - size[1] / 2
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    cells = np.stack([gx.ravel(), gy.ravel()], axis=1) + np.array(region.position[:2])
    marked = np.zeros(len(cells), dtype=bool)
    for pose in poses:
        if pose.position[2] > surface + IN_CONTACT:
            continue
        yaw = quat.to_euler(pose.orientation)[2]
        c, s = math.cos(yaw), math.sin(yaw)
        d = cells - np.array(pose.position[:2])
        along, across = d[:, 0] * c + d[:, 1] * s, -d[:, 0] * s + d[:, 1] * c
        marked |= (np.abs(along) <= footprint[0] / 2) & (np.abs(across) <= footprint[1] / 2)
    return float(marked.mean())

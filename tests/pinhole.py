"""A pinhole camera written for the tests, apart from the code that aims cameras: where map
points fall in a view, so a test can judge what a picture shows."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np


def view_axes(eye: Sequence[float], target: Sequence[float]) -> tuple[np.ndarray, ...]:
    """The unit forward, right and up axes of a level camera at ``eye`` facing ``target``."""
    forward = np.subtract(target, eye).astype(float)
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, (0.0, 0.0, 1.0))
    right /= np.linalg.norm(right)
    return forward, right, np.cross(right, forward)


def view_offsets(
    points: np.ndarray, eye: Sequence[float], target: Sequence[float], fov: float
) -> np.ndarray:
    """(right, up) of each point as a share of the half-height of a view ``fov`` [rad]
    high: in a square view if both lie within 1. Every point must be in front."""
    forward, right, up = view_axes(eye, target)
    rel = points - np.asarray(eye, dtype=float)
    depth = rel @ forward
    assert (depth > 0).all(), "a point behind the camera"
    half = math.tan(fov / 2) * depth
    return np.stack([(rel @ right) / half, (rel @ up) / half], axis=1)


def box_corners(low: Sequence[float], high: Sequence[float]) -> np.ndarray:
    """The eight corners of the box from ``low`` to ``high``."""
    return np.array(
        [[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])]
    )

"""Blended corners: used only where the checker finds the blend free, else a rest there.

Two joints, a corner turning 0.3 rad between segments 0.4 long (a blend of radius 0.2
cuts 11 mm into the corner, one of 0.05 cuts 2.8 mm), and a ball-shaped obstacle inside
the corner that the polyline clears. A fake clearance checker measures the distance to
the ball (a lever of 1 m/rad: joint space is the workspace).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from robocram.motion import JointLimits, time_parameterize
from robocram.motion.corner_blend import SHRINK, blend_radii
from robocram.motion.travel_bound import TravelBound

LIMITS = (
    JointLimits("a", -5.0, 5.0, 1.0, 2.0, 20.0),
    JointLimits("b", -5.0, 5.0, 1.0, 2.0, 20.0),
)
TURN = 2.0 * math.asin(0.15)  # [rad] the corner's turn: |u2 - u1| = 0.3
PATH = np.array(
    [[-0.4, 0.0], [0.0, 0.0], [0.4 * math.cos(TURN), 0.4 * math.sin(TURN)]]
)  # fmt: skip
INWARD = np.array([-math.sin(TURN / 2), math.cos(TURN / 2)])  # the corner's inner bisector


class Ball:
    """A clearance checker of two joints against a ball [m]."""

    joints = ("a", "b")
    reach = 0.1

    def __init__(self, centre: np.ndarray | None, radius: float) -> None:
        self.centre, self.radius, self.asked = centre, radius, 0

    def clearances(self, q: np.ndarray) -> dict[str, float]:
        self.asked += 1
        if self.centre is None:
            return {}
        return {"link": min(float(np.linalg.norm(q - self.centre)) - self.radius, self.reach)}

    def clearance(self, q: np.ndarray) -> float:
        return min(self.clearances(q).values(), default=self.reach)

    def is_free(self, q: np.ndarray) -> bool:
        return self.clearance(q) > 0.0

    def colliding(self, q: np.ndarray, first_only: bool = False) -> list[tuple[str, str]]:
        return [] if self.is_free(q) else [("link", "ball")]


BOUND = TravelBound(("a", "b"), lever=np.ones(2))


def _off_polyline(point: np.ndarray) -> float:
    best = math.inf
    for a, b in zip(PATH[:-1], PATH[1:], strict=True):
        d = b - a
        s = min(max(float((point - a) @ d / (d @ d)), 0.0), 1.0)
        best = min(best, float(np.linalg.norm(point - a - s * d)))
    return best


@pytest.mark.parametrize(
    ("centre_inward", "radius", "expected"),
    [
        (None, 0.0, 0.2),  # nothing near: half the shorter segment
        (0.05, 0.045, 0.2 * SHRINK),  # the full blend would cut into the ball
        (0.02, 0.0195, 0.0),  # so would the quarter: the robot rests at the corner
    ],
)
def test_a_blend_is_kept_only_where_the_checker_finds_it_free(
    centre_inward: float | None, radius: float, expected: float
) -> None:
    centre = None if centre_inward is None else centre_inward * INWARD
    checker = Ball(centre, radius)
    assert all(checker.is_free(p) for p in PATH)
    radii = blend_radii(checker, BOUND, PATH)
    assert radii == pytest.approx((expected,), rel=1e-12)
    assert checker.asked > 0
    timed = time_parameterize("robot", ("a", "b"), PATH, LIMITS, corner_radii=radii, period=0.002)
    positions = timed.positions()
    assert all(checker.is_free(q) for q in positions)
    deviation = max(_off_polyline(q) for q in positions)
    assert deviation <= 3.0 / 16.0 * expected * 0.3 + 1e-9
    corner = int(np.argmin(np.linalg.norm(positions, axis=1)))
    speed = float(np.linalg.norm(timed.points[corner].velocities))
    if expected == 0.2:  # passed without stopping, cutting the corner
        assert deviation > 0.5 * 3.0 / 16.0 * expected * 0.3 and speed > 0.05
    if expected == 0.0:  # at rest on the corner itself
        assert deviation < 1e-9 and speed == 0.0
    np.testing.assert_allclose(positions[-1], PATH[-1], atol=1e-12)


def test_a_sharp_corner_is_never_blended() -> None:
    path = np.array([[0.0, 0.0], [0.4, 0.0], [0.0, 0.1]])
    assert blend_radii(Ball(None, 0.0), BOUND, path) == (0.0,)

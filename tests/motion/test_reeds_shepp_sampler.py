"""The Reeds-Shepp sampler gives OMPL's own interpolation, bit for bit: each state at
``j / n`` along the curve equals what ``ReedsSheppStateSpace.interpolate`` returns for it
(the curve solved again for every state), read here by raw OMPL calls."""

from __future__ import annotations

import numpy as np
import pytest
from ompl import base as ob

from robocram.motion.planar_motion import reeds_shepp_poses, wrapped
from robocram.motion.reeds_shepp_sampler import ReedsSheppSampler, sampler_for


def _ompl_states(radius: float, start: np.ndarray, end: np.ndarray, n: int) -> np.ndarray:
    """OMPL's ``interpolate`` at ``j / n`` (j = 1..n), one call per state."""
    space = ob.ReedsSheppStateSpace(radius)
    a, b, out = space.allocState(), space.allocState(), space.allocState()
    for state, pose in ((a, start), (b, end)):
        state.setX(float(pose[0]))
        state.setY(float(pose[1]))
        state.setYaw(float(pose[2]))
    rows = []
    for j in range(1, n + 1):
        space.interpolate(a, b, j / n, out)
        rows.append((out.getX(), out.getY(), out.getYaw()))
    return np.array(rows)


def _pose(rng: np.random.Generator) -> np.ndarray:
    return np.array([*rng.uniform(-4.0, 4.0, 2), rng.uniform(-np.pi, np.pi)])


@pytest.mark.parametrize("radius", [0.2, 0.5])
def test_the_sampled_states_are_ompls_interpolation_bit_for_bit(radius: float) -> None:
    rng = np.random.default_rng(3)
    sampler = ReedsSheppSampler(radius)
    for k in range(120):
        start = _pose(rng)
        end = _pose(rng) if k % 2 else start + np.array([*rng.uniform(-0.2, 0.2, 2), 0.0])
        end[2] = wrapped(float(end[2]))
        n = int(rng.integers(1, 400))
        assert np.array_equal(sampler.states(start, end, n), _ompl_states(radius, start, end, n))


def test_standing_still_and_a_length_are_ompls() -> None:
    sampler = ReedsSheppSampler(0.3)
    here = np.array([1.0, -2.0, 0.5])
    assert np.array_equal(sampler.states(here, here, 3), _ompl_states(0.3, here, here, 3))
    there = np.array([1.5, -1.0, -2.0])
    space = ob.ReedsSheppStateSpace(0.3)
    a, b = space.allocState(), space.allocState()
    for state, pose in ((a, here), (b, there)):
        state.setX(float(pose[0]))
        state.setY(float(pose[1]))
        state.setYaw(float(pose[2]))
    assert sampler.length(here, there) == space.distance(a, b)


def test_dense_poses_end_at_the_goal_with_continuous_headings() -> None:
    start, end = np.array([0.0, 0.0, 3.0]), np.array([0.4, 0.3, -3.0 + 4 * np.pi])
    poses = reeds_shepp_poses(sampler_for(0.3), start, end, reach=0.5)
    assert np.array_equal(poses[0], start)
    assert np.array_equal(poses[-1, :2], end[:2])
    assert abs(wrapped(float(poses[-1, 2] - end[2]))) < 1e-12
    assert np.all(np.abs(np.diff(poses[:, 2])) <= 0.02 + 1e-12)  # no jump of 2 pi

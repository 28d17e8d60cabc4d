"""Timing is bounded in what grows with its input: waypoints and samples, each bound named
in its error and checked before anything is allocated (issue 42, bad 3)."""

from __future__ import annotations

import numpy as np
import pytest

from robocram.motion import JointLimits, joint_limits
from robocram.motion.errors import MotionInputError
from robocram.motion.time_parameterization import (
    MAX_TRAJECTORY_POINTS,
    MAX_WAYPOINTS,
    time_parameterize,
)
from robocram.robots import load_description

PR2 = load_description("pr2")
ARM = PR2.arms["right"].joints
LIMITS = joint_limits(PR2, ARM)
START = np.array([-1.0, 0.2, -0.5, -1.2, 0.3, -0.6, 0.0])
END = np.array([-0.4, 0.6, -0.9, -0.5, 1.5, -0.3, 2.0])


def test_a_tiny_period_is_refused_before_sampling() -> None:
    with pytest.raises(MotionInputError) as caught:
        time_parameterize("pr2", ARM, [START, END], LIMITS, period=1e-9)
    assert caught.value.bound == MAX_TRAJECTORY_POINTS
    assert "MAX_TRAJECTORY_POINTS" in str(caught.value) and "1e-09 s" in str(caught.value)


def test_too_many_waypoints_are_refused_before_timing() -> None:
    zigzag = np.array([START if k % 2 else END for k in range(MAX_WAYPOINTS + 1)])
    with pytest.raises(MotionInputError) as caught:
        time_parameterize("pr2", ARM, zigzag, LIMITS)
    assert caught.value.value == MAX_WAYPOINTS + 1 and caught.value.bound == MAX_WAYPOINTS
    assert "MAX_WAYPOINTS" in str(caught.value)


def test_sizes_within_the_bounds_are_timed() -> None:
    trajectory = time_parameterize("pr2", ARM, [START, END], LIMITS, period=1e-3)
    assert 1_000 < len(trajectory.points) < MAX_TRAJECTORY_POINTS
    assert trajectory.points[-1].positions == pytest.approx(END.tolist(), abs=1e-12)


@pytest.mark.parametrize(("velocity", "acceleration"), [(1e-300, 1.0), (1.0, 1e-300), (1e300, 1.0)])
def test_rates_ruckig_cannot_time_are_refused_naming_the_joint(
    velocity: float, acceleration: float
) -> None:
    limits = (JointLimits("j", -10.0, 10.0, velocity, acceleration, 10.0 * acceleration),)
    with pytest.raises(MotionInputError) as caught:
        time_parameterize("r", ["j"], [[0.0], [1.0]], limits)
    assert caught.value.joint == "j" and "MIN_RATE_LIMIT" in str(caught.value)

"""Euler angles round-trip, including the gimbal-lock poses URDF writing meets."""

from __future__ import annotations

import math
import random

import pytest

from robocram.tf import quaternion as quat


def test_random_rpy_round_trip_rebuilds_the_rotation() -> None:
    rng = random.Random(7)
    for _ in range(2000):
        rpy = (rng.uniform(-3, 3), rng.uniform(-1.57, 1.57), rng.uniform(-3, 3))
        q = quat.from_euler(*rpy)
        assert (
            quat.angle_between(q, quat.from_euler(*quat.to_euler(q))) < 1e-6
        )  # acos near 1 resolves ~3e-8


@pytest.mark.parametrize(
    "q", [(0.5, 0.5, 0.5, -0.5), (0.5, -0.5, 0.5, 0.5), (0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5))]
)
def test_pitch_of_a_quarter_turn_keeps_the_rotation(q: quat.Quaternion) -> None:
    unit = quat.normalized(q)
    roll, pitch, yaw = quat.to_euler(unit)
    assert abs(abs(pitch) - math.pi / 2) < 1e-6  # acos near 1 resolves ~3e-8
    assert (
        quat.angle_between(unit, quat.from_euler(roll, pitch, yaw)) < 1e-6
    )  # acos near 1 resolves ~3e-8

"""Checks of the trajectory goals a driver received (its goal log) against those sent."""

from __future__ import annotations

from typing import Any

import pytest

from robocram.motion import JointTrajectory

SAME = 1e-9  # [rad | s] what crosses ROS unchanged (float64; times to the nanosecond)


def seconds(duration: dict[str, int]) -> float:
    """A logged ROS duration in seconds."""
    return duration["secs"] + duration["nsecs"] * 1e-9


def assert_same_goal(received: dict[str, Any], sent: JointTrajectory) -> None:
    """The goal the driver got is ``sent``: names, points, times, velocities, accelerations."""
    trajectory = received["trajectory"]
    assert trajectory["joint_names"] == list(sent.joint_names)
    assert len(trajectory["points"]) == len(sent.points)
    for got, want in zip(trajectory["points"], sent.points, strict=True):
        assert seconds(got["time_from_start"]) == pytest.approx(want.time_from_start, abs=SAME)
        for key in ("positions", "velocities", "accelerations"):
            assert got[key] == pytest.approx(list(getattr(want, key)), abs=SAME)

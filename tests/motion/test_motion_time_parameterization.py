"""Timing a joint-space polyline: on the polyline, within limits, at rest at the end."""

from __future__ import annotations

import dataclasses
import math
import pickle

import numpy as np
import pytest
from ruckig import InputParameter, Ruckig, Trajectory

from robocram.motion import JointLimits, JointTrajectory, MotionError, joint_limits
from robocram.motion.straight_segment import along_line_segment, profile_states, straight_segment
from robocram.motion.time_parameterization import time_parameterize
from robocram.robots import load_description

PR2 = load_description("pr2")
ARM = PR2.arms["right"].joints
LIMITS = joint_limits(PR2, ARM)
PATH = np.array(
    [
        [-1.0, 0.2, -0.5, -1.2, 0.3, -0.6, 0.0],
        [-0.4, 0.6, -0.9, -0.5, 1.5, -0.3, 2.0],
        [-0.9, -0.1, -0.2, -1.0, -0.2, -1.1, -1.0],
    ]
)


def _distance_to_polyline(point: np.ndarray, path: np.ndarray) -> float:
    best = math.inf
    for a, b in zip(path[:-1], path[1:], strict=True):
        d = b - a
        s = min(max(float(np.dot(point - a, d) / np.dot(d, d)), 0.0), 1.0)
        best = min(best, float(np.linalg.norm(point - (a + s * d))))
    return best


def _min_segment_time(a: np.ndarray, b: np.ndarray, limits: tuple[JointLimits, ...]) -> float:
    """The slowest joint's own jerk-limited time, straight from ruckig."""
    params = InputParameter(len(a))
    params.current_position, params.target_position = list(a), list(b)
    params.max_velocity = [lim.velocity for lim in limits]
    params.max_acceleration = [lim.acceleration for lim in limits]
    params.max_jerk = [lim.jerk for lim in limits]
    trajectory = Trajectory(len(a))
    Ruckig(len(a)).calculate(params, trajectory)
    return max(trajectory.independent_min_durations)


@pytest.fixture(scope="module")
def timed() -> JointTrajectory:
    return time_parameterize("pr2", ARM, PATH, LIMITS)


def test_every_point_on_the_polyline(timed: JointTrajectory) -> None:
    positions = timed.positions()
    assert max(_distance_to_polyline(p, PATH) for p in positions) < 1e-6
    np.testing.assert_allclose(positions[0], PATH[0], atol=1e-12)
    np.testing.assert_allclose(positions[-1], PATH[-1], atol=1e-12)
    for waypoint in PATH:  # every waypoint is a sample
        assert np.min(np.linalg.norm(positions - waypoint, axis=1)) < 1e-12


def test_within_velocity_and_acceleration_limits(timed: JointTrajectory) -> None:
    velocity = np.array([lim.velocity for lim in LIMITS])
    acceleration = np.array([lim.acceleration for lim in LIMITS])
    jerk = np.array([lim.jerk for lim in LIMITS])
    v = np.array([p.velocities for p in timed.points])
    a = np.array([p.accelerations for p in timed.points])
    assert np.all(np.abs(v) <= velocity * (1 + 1e-6))
    assert np.all(np.abs(a) <= acceleration * (1 + 1e-6))
    times, q = timed.times(), timed.positions()
    dt = np.diff(times)[:, None]
    fd_velocity = np.diff(q, axis=0) / dt
    assert np.all(np.abs(fd_velocity) <= velocity * (1 + 1e-6))
    mid = 0.5 * (times[1:] + times[:-1])
    fd_acceleration = np.diff(fd_velocity, axis=0) / np.diff(mid)[:, None]
    # a difference quotient of a jerk-limited motion: within the limit plus jerk x spacing
    assert np.all(np.abs(fd_acceleration) <= acceleration + jerk * 0.05)


def test_times_rest_and_duration(timed: JointTrajectory) -> None:
    times = timed.times()
    assert times[0] == 0.0
    assert np.all(np.diff(times) > 0.0)
    assert np.all(np.diff(times) <= 0.05 + 1e-12)
    assert timed.points[-1].velocities == pytest.approx([0.0] * 7, abs=1e-9)
    assert timed.points[0].velocities == pytest.approx([0.0] * 7, abs=1e-9)
    minimum = sum(_min_segment_time(a, b, LIMITS) for a, b in zip(PATH[:-1], PATH[1:], strict=True))
    assert minimum - 1e-9 <= timed.duration <= 1.05 * minimum
    assert timed.kind == "arm" and timed.joint_names == ARM


def test_deterministic_pickles_and_to_ros(timed: JointTrajectory) -> None:
    assert time_parameterize("pr2", ARM, PATH, LIMITS) == timed
    assert pickle.loads(pickle.dumps(timed)) == timed
    message = timed.to_ros()
    stamps = [
        p["time_from_start"]["secs"] + 1e-9 * p["time_from_start"]["nsecs"]
        for p in message["points"]  # type: ignore[attr-defined]
    ]
    np.testing.assert_allclose(stamps, timed.times(), atol=1e-9)
    assert message["joint_names"] == list(ARM)


def test_a_dense_path_rests_at_its_corners_and_passes_collinear_waypoints() -> None:
    """A corner passed at speed is a velocity step (unbounded acceleration): the robot
    rests at each; waypoints on the line through their neighbours are no corners."""
    s = np.linspace(0.0, 0.4, 41)  # 40 segments of 1 cm of travel, gently curving
    dense = np.stack(
        [-1.0 + s, 0.2 + 0.5 * s**2, -0.5 - 0.3 * s, -1.2 + 0.2 * s, 0.3 * np.ones_like(s),
         -0.6 + 0.1 * s, 0.0 * s],
        axis=1,
    )  # fmt: skip
    timed = time_parameterize("pr2", ARM, dense, LIMITS)
    assert max(_distance_to_polyline(p, dense) for p in timed.positions()) < 1e-6
    stop_and_go = sum(
        _min_segment_time(a, b, LIMITS) for a, b in zip(dense[:-1], dense[1:], strict=True)
    )
    assert timed.duration == pytest.approx(stop_and_go, rel=1e-6)
    positions, v = timed.positions(), np.array([p.velocities for p in timed.points])
    for waypoint in dense:
        row = int(np.argmin(np.linalg.norm(positions - waypoint, axis=1)))
        assert np.abs(v[row]).max() < 1e-12
    line = np.array([PATH[0] + f * (PATH[1] - PATH[0]) for f in (0.0, 0.3, 0.7, 1.0)])
    straight = time_parameterize("pr2", ARM, line, LIMITS)
    assert straight.duration == pytest.approx(_min_segment_time(PATH[0], PATH[1], LIMITS), rel=1e-6)


def test_continuous_yaw_and_a_one_point_path() -> None:
    base = joint_limits(PR2, ("x", "y", "yaw"))
    timed = time_parameterize("pr2", ("x", "y", "yaw"), [[0, 0, 3.0], [1, 0, 7.0]], base,
                              kind="base")  # fmt: skip
    assert timed.kind == "base"
    assert timed.end == pytest.approx({"x": 1.0, "y": 0.0, "yaw": 7.0})
    assert max(abs(p.velocities[2]) for p in timed.points) <= 1.0 + 1e-6
    single = time_parameterize("pr2", ARM, PATH[:1], LIMITS)
    assert len(single.points) == 1 and single.duration == 0.0


def test_the_line_profile_matches_phase_synchronisation() -> None:
    a, b = PATH[0], PATH[1]
    synced, line = straight_segment(a, b, LIMITS), along_line_segment(a, b, LIMITS)
    assert line.duration == pytest.approx(synced.duration, rel=1e-6)
    for t in np.linspace(0.0, synced.duration, 9):
        np.testing.assert_allclose(line.state(t)[0], synced.state(t)[0], atol=1e-6)


@pytest.mark.parametrize(
    ("path", "fragment"),
    [
        ([[0.0] * 6], "shape (6,)"),
        ([[-1.0, 0.2, -0.5, -1.2, math.nan, -0.6, 0.0]], "'r_forearm_roll_joint'"),
        ([[-1.0, 5.0, -0.5, -1.2, 0.3, -0.6, 0.0]], "outside its limits"),
        ([], "no waypoints"),
    ],
)
def test_bad_paths_are_named(path: list[list[float]], fragment: str) -> None:
    with pytest.raises(MotionError, match=fragment.replace("(", r"\(").replace(")", r"\)")):
        time_parameterize("pr2", ARM, path, LIMITS)


def test_limits_for_other_joints_are_refused() -> None:
    with pytest.raises(MotionError, match="joint_limits"):
        time_parameterize("pr2", ARM, PATH, LIMITS[::-1])


def test_a_profile_sampled_at_once_is_ruckig_at_each_time_bit_for_bit() -> None:
    rng = np.random.default_rng(5)
    for _ in range(40):
        a = rng.uniform(-1.5, 1.5, 7)
        b = a + rng.normal(0.0, 1.0, 7) * (rng.random(7) > 0.3)
        b[0] += 0.1  # never the same point
        for segment in (straight_segment(a, b, LIMITS), along_line_segment(a, b, LIMITS)):
            trajectory = segment.trajectory
            times = np.concatenate((np.linspace(0.0, trajectory.duration, 50), [0.3]))
            at_once = profile_states(trajectory, np.minimum(times, trajectory.duration))
            for row, t in enumerate(np.minimum(times, trajectory.duration)):
                one = trajectory.at_time(float(t))
                for k in range(3):
                    assert at_once[k][row].tolist() == list(one[k])


@pytest.mark.parametrize("value", [0.0, -1.0, math.nan, math.inf])
def test_limits_that_are_not_positive_and_finite_are_named(value: float) -> None:
    bad = list(LIMITS)
    bad[2] = dataclasses.replace(LIMITS[2], acceleration=value)
    with pytest.raises(MotionError, match=rf"joint '{ARM[2]}' has .*positive and finite"):
        time_parameterize("pr2", ARM, PATH, bad)

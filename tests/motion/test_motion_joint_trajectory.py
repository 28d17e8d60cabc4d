"""The trajectory value: its checks, its sampling, its ROS message and its pickling."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from robocram.motion import JointTrajectory, TrajectoryPoint, still
from robocram.motion.joint_trajectory import PointTable


def _two_points() -> JointTrajectory:
    a = TrajectoryPoint((0.0, 1.0), (0.0, 0.0), (0.0, 0.0), 0.0)
    b = TrajectoryPoint((1.0, 3.0), (0.0, 0.0), (0.0, 0.0), 2.0)
    return JointTrajectory("pr2", ("j1", "j2"), (a, b))


def test_positions_between_points_are_linear_and_clamped_at_the_ends() -> None:
    trajectory = _two_points()
    assert trajectory.at(0.5).tolist() == pytest.approx([0.25, 1.5])
    assert trajectory.at(-1.0).tolist() == [0.0, 1.0]
    assert trajectory.at(9.0).tolist() == [1.0, 3.0]
    assert trajectory.start == {"j1": 0.0, "j2": 1.0} and trajectory.end == {"j1": 1.0, "j2": 3.0}


def test_sampling_covers_the_motion_and_a_still_one_is_one_sample() -> None:
    samples = list(_two_points().sampled(0.5))
    assert [t for t, _ in samples] == pytest.approx([0.0, 0.5, 1.0, 1.5, 2.0])
    assert samples[-1][1] == {"j1": 1.0, "j2": 3.0}
    assert len(list(still("pr2", ("j1",), (0.3,)).sampled(0.05))) == 1
    with pytest.raises(ValueError, match="period"):
        list(_two_points().sampled(0.0))


def test_times_must_increase_and_widths_match() -> None:
    a = TrajectoryPoint((0.0,), (0.0,), (0.0,), 1.0)
    with pytest.raises(ValueError, match="not after"):
        JointTrajectory("pr2", ("j1",), (a, a))
    with pytest.raises(ValueError, match="1 positions for 2 joints"):
        JointTrajectory("pr2", ("j1", "j2"), (a,))


def test_the_ros_message_carries_every_point_to_the_nanosecond_and_it_pickles() -> None:
    trajectory = _two_points()
    message = trajectory.to_ros()
    assert message["joint_names"] == ["j1", "j2"]
    points = message["points"]
    assert isinstance(points, list) and len(points) == 2
    assert points[1]["time_from_start"] == {"secs": 2, "nsecs": 0}
    assert points[1]["positions"] == [1.0, 3.0]
    assert pickle.loads(pickle.dumps(trajectory)) == trajectory


def _table() -> PointTable:
    positions = np.array([[0.0, 1.0], [0.5, 2.0], [1.0, 3.0]])
    rates = np.array([[0.0, 0.0], [0.5, 1.0], [0.0, 0.0]])
    return PointTable(positions, rates, -rates, np.array([0.0, 1.0, 2.0]))


def test_a_point_table_reads_as_the_tuple_of_its_points() -> None:
    table = _table()
    points = tuple(table)
    assert len(table) == 3 and table[1] == points[1] and table[-1] == points[2]
    assert points[1] == TrajectoryPoint((0.5, 2.0), (0.5, 1.0), (-0.5, -1.0), 1.0)
    assert all(type(v) is float for p in points for v in (*p.positions, p.time_from_start))
    assert table == points and points == table and hash(table) == hash(points)
    assert table[:2] == points[:2] and isinstance(table[:2], PointTable)
    with pytest.raises(ValueError, match="read-only"):
        table.positions[0, 0] = 9.0


def test_a_tabled_trajectory_is_the_same_value_as_one_of_points() -> None:
    table = _table()
    tabled = JointTrajectory("pr2", ("j1", "j2"), table)
    listed = JointTrajectory("pr2", ("j1", "j2"), tuple(_table()))
    assert tabled == listed and hash(tabled) == hash(listed)
    assert tabled.duration == listed.duration == 2.0 and tabled.end == listed.end
    assert tabled.positions().tolist() == listed.positions().tolist()
    assert tabled.times().tolist() == listed.times().tolist()
    assert tabled.to_ros() == listed.to_ros()
    again = pickle.loads(pickle.dumps(tabled))
    assert again == tabled and isinstance(again.points, PointTable)


def test_a_point_table_is_checked_as_points_are() -> None:
    table = _table()
    with pytest.raises(ValueError, match="point 0 has 2 positions for 3 joints"):
        JointTrajectory("pr2", ("j1", "j2", "j3"), table)
    late = PointTable(table.positions, table.positions, table.positions, np.array([0, 2, 2.0]))
    with pytest.raises(ValueError, match="point 2 is at 2.0 s, not after point 1 at 2.0 s"):
        JointTrajectory("pr2", ("j1", "j2"), late)
    with pytest.raises(ValueError, match="point table needs"):
        PointTable(table.positions, table.positions, table.positions, np.zeros(2))


def test_a_point_table_keeps_its_own_copy() -> None:
    positions = np.zeros((2, 1))
    table = PointTable(positions, positions, positions, np.array([0.0, 1.0]))
    positions[1, 0] = 5.0  # the caller's array stays writable and the table unchanged
    assert table[1].positions == (0.0,)

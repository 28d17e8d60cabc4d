"""Stamped values and their ROS JSON-bridge dictionaries."""

from __future__ import annotations

import math

import pytest

from robocram.tf import (
    Pose,
    PoseStamped,
    RosMessageError,
    TransformStamped,
    pose_from_ros,
    pose_stamped_from_ros,
    pose_stamped_to_ros,
    pose_to_ros,
    transform_stamped_from_ros,
    transform_stamped_to_ros,
)
from robocram.tf import quaternion as quat


def test_pose_stamped_shapes() -> None:
    ps = PoseStamped("map", (1.5, 0, 1))
    assert ps.orientation == (0.0, 0.0, 0.0, 1.0) and ps.stamp == 0.0
    assert Pose.coerce(ps) == Pose((1.5, 0, 1))
    other = ps.with_frame("odom")
    assert other.frame_id == "odom" and other.position == ps.position
    assert PoseStamped.from_pose("base", ((1, 2, 3), (0, 0, 1, 1)), 2.0).orientation == (
        pytest.approx((0, 0, math.sqrt(0.5), math.sqrt(0.5)))
    )
    with pytest.raises(ValueError, match="frame_id"):
        PoseStamped("", (0, 0, 0))
    with pytest.raises(ValueError, match="stamp"):
        PoseStamped("map", stamp=math.nan)


def test_transform_stamped_inverse() -> None:
    t = TransformStamped("map", "base", (1, 2, 0), quat.from_euler(0, 0, 1.0), stamp=4.0)
    inv = t.inverse()
    assert (inv.frame_id, inv.child_frame_id, inv.stamp) == ("base", "map", 4.0)
    ident = t.as_pose() * inv.pose
    assert ident.distance_to(Pose()) < 1e-12 and ident.angle_to(Pose()) < 1e-7


def test_pose_stamped_ros_round_trip_both_stamp_styles() -> None:
    ps = PoseStamped("base_footprint", (0.1, -0.2, 0.3), quat.from_euler(0.1, 0.2, 0.3), 12.25)
    d1 = pose_stamped_to_ros(ps)
    assert d1["header"] == {
        "frame_id": "base_footprint",
        "stamp": {"secs": 12, "nsecs": 250_000_000},
    }
    assert d1["pose"]["position"] == {"x": 0.1, "y": -0.2, "z": 0.3}
    assert set(d1["pose"]["orientation"]) == {"x", "y", "z", "w"}
    d2 = pose_stamped_to_ros(ps, ros2=True)
    assert d2["header"]["stamp"] == {"sec": 12, "nanosec": 250_000_000}
    for d in (d1, d2):
        back = pose_stamped_from_ros(d)
        assert back.frame_id == ps.frame_id and back.stamp == pytest.approx(12.25)
        assert back.position == pytest.approx(ps.position)
        assert back.orientation == pytest.approx(ps.orientation)


def test_transform_stamped_ros_round_trip() -> None:
    t = TransformStamped("odom", "base_link", (1, 0, 0.05), quat.from_euler(0, 0, -0.5), 1.5)
    d = transform_stamped_to_ros(t)
    assert d["child_frame_id"] == "base_link"
    assert d["transform"]["translation"] == {"x": 1.0, "y": 0.0, "z": 0.05}
    back = transform_stamped_from_ros(d)
    assert back.frame_id == "odom" and back.child_frame_id == "base_link"
    assert back.rotation == pytest.approx(t.rotation) and back.stamp == pytest.approx(1.5)


def test_pose_round_trip_and_missing_stamp() -> None:
    p = Pose((1, 2, 3), quat.from_euler(0, 0, 2))
    assert pose_from_ros(pose_to_ros(p)).orientation == pytest.approx(p.orientation)
    no_stamp = {"header": {"frame_id": "map"}, "pose": pose_to_ros(p)}
    assert pose_stamped_from_ros(no_stamp).stamp == 0.0


def test_malformed_dicts_name_the_missing_key() -> None:
    good = pose_stamped_to_ros(PoseStamped("map", (1, 0, 0)))
    del good["pose"]["orientation"]["w"]
    with pytest.raises(RosMessageError, match=r"'pose\.orientation\.w'") as info:
        pose_stamped_from_ros(good)
    assert info.value.path == "pose.orientation.w"
    with pytest.raises(RosMessageError, match=r"'header'"):
        pose_stamped_from_ros({"pose": {}})
    bad_type = pose_stamped_to_ros(PoseStamped("map"))
    bad_type["pose"]["position"]["x"] = "one"
    with pytest.raises(RosMessageError, match=r"'pose\.position\.x' must be a number"):
        pose_stamped_from_ros(bad_type)
    with pytest.raises(RosMessageError, match="child_frame_id"):
        transform_stamped_from_ros({"header": {"frame_id": "map"}, "transform": {}})

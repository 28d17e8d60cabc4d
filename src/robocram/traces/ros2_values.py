"""ROS 2 message values as the MCAP writer encodes them: nested dicts of plain numbers.

Stamps are float seconds since the epoch on the run's replay clock; poses are ours
(:class:`robocram.tf.Pose`), quaternions ``(x, y, z, w)`` as ROS orders them too.
"""

from __future__ import annotations

from robocram.tf import Pose

Value = dict[str, object]  # one message (or nested message) as the encoder takes it


def header(time: float, frame: str) -> Value:
    """A ``std_msgs/Header`` stamped ``time`` [s since the epoch] in ``frame``."""
    sec = int(time // 1)
    nanosec = min(int(round((time - sec) * 1e9)), 999_999_999)
    return {"stamp": {"sec": sec, "nanosec": nanosec}, "frame_id": frame}


def transform(pose: Pose) -> Value:
    """A ``geometry_msgs/Transform`` of ``pose``."""
    (x, y, z), (qx, qy, qz, qw) = pose.position, pose.orientation
    return {
        "translation": {"x": x, "y": y, "z": z},
        "rotation": {"x": qx, "y": qy, "z": qz, "w": qw},
    }


def pose_value(pose: Pose) -> Value:
    """A ``geometry_msgs/Pose`` of ``pose``."""
    (x, y, z), (qx, qy, qz, qw) = pose.position, pose.orientation
    return {
        "position": {"x": x, "y": y, "z": z},
        "orientation": {"x": qx, "y": qy, "z": qz, "w": qw},
    }

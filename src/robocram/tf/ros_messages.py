"""Conversions to and from the dictionaries that ROS JSON bridges (rosbridge) exchange.

``geometry_msgs/Pose``, ``PoseStamped`` and ``TransformStamped`` as nested dicts. Stamps
are written ROS 1 style (``{"secs", "nsecs"}``) unless ``ros2=True`` (``{"sec",
"nanosec"}``); both styles are read. A missing or ill-typed key raises
:class:`~robocram.tf.errors.RosMessageError` naming its dotted path.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from robocram.tf.errors import RosMessageError
from robocram.tf.pose import Pose
from robocram.tf.stamped import PoseStamped, TransformStamped

RosDict = dict[str, Any]


def _get(d: object, key: str, path: str) -> Any:
    if not isinstance(d, Mapping):
        raise RosMessageError(f"ROS message field {path or '<root>'!r} must be a dict", path)
    where = f"{path}.{key}" if path else key
    if key not in d:
        raise RosMessageError(f"ROS message lacks key {where!r}; present keys: {sorted(d)}", where)
    return d[key]


def _number(d: object, key: str, path: str) -> float:
    value = _get(d, key, path)
    if isinstance(value, bool) or not isinstance(value, int | float):
        where = f"{path}.{key}" if path else key
        raise RosMessageError(f"ROS message field {where!r} must be a number, got {value!r}", where)
    return float(value)


def _xyz(d: object, path: str) -> tuple[float, float, float]:
    return (_number(d, "x", path), _number(d, "y", path), _number(d, "z", path))


def _xyzw(d: object, path: str) -> tuple[float, float, float, float]:
    return (*_xyz(d, path), _number(d, "w", path))


def _vector(v: tuple[float, ...], keys: str) -> dict[str, float]:
    return dict(zip(keys, v, strict=True))


def stamp_to_ros(stamp: float, ros2: bool = False) -> dict[str, int]:
    """Split ``stamp`` [s] into whole seconds and nanoseconds."""
    secs = math.floor(stamp)
    nsecs = min(round((stamp - secs) * 1e9), 999_999_999)
    return {"sec": secs, "nanosec": nsecs} if ros2 else {"secs": secs, "nsecs": nsecs}


def stamp_from_ros(d: object, path: str = "header.stamp") -> float:
    """Time [s] of a ROS 1 ``{"secs", "nsecs"}`` or ROS 2 ``{"sec", "nanosec"}`` stamp."""
    if isinstance(d, Mapping) and "sec" in d:
        return _number(d, "sec", path) + _number(d, "nanosec", path) * 1e-9
    return _number(d, "secs", path) + _number(d, "nsecs", path) * 1e-9


def _header_to_ros(frame_id: str, stamp: float, ros2: bool) -> RosDict:
    return {"frame_id": frame_id, "stamp": stamp_to_ros(stamp, ros2)}


def _header_from_ros(d: object) -> tuple[str, float]:
    header = _get(d, "header", "")
    frame_id = _get(header, "frame_id", "header")
    if not isinstance(frame_id, str) or not frame_id:
        raise RosMessageError(
            f"header.frame_id must be a non-empty frame name, got {frame_id!r}",
            "header.frame_id",
        )
    stamp = stamp_from_ros(header["stamp"]) if "stamp" in header else 0.0
    return frame_id, stamp


def pose_to_ros(pose: Pose) -> RosDict:
    """``geometry_msgs/Pose`` dict of ``pose``."""
    return {
        "position": _vector(pose.position, "xyz"),
        "orientation": _vector(pose.orientation, "xyzw"),
    }


def pose_from_ros(d: object, path: str = "") -> Pose:
    """Pose of a ``geometry_msgs/Pose`` dict."""
    prefix = f"{path}." if path else ""
    position = _xyz(_get(d, "position", path), f"{prefix}position")
    orientation = _xyzw(_get(d, "orientation", path), f"{prefix}orientation")
    return Pose(position, orientation)


def pose_stamped_to_ros(pose: PoseStamped, ros2: bool = False) -> RosDict:
    """``geometry_msgs/PoseStamped`` dict of ``pose``."""
    return {
        "header": _header_to_ros(pose.frame_id, pose.stamp, ros2),
        "pose": pose_to_ros(pose.pose),
    }


def pose_stamped_from_ros(d: object) -> PoseStamped:
    """PoseStamped of a ``geometry_msgs/PoseStamped`` dict."""
    frame_id, stamp = _header_from_ros(d)
    return PoseStamped.from_pose(frame_id, pose_from_ros(_get(d, "pose", ""), "pose"), stamp)


def transform_stamped_to_ros(transform: TransformStamped, ros2: bool = False) -> RosDict:
    """``geometry_msgs/TransformStamped`` dict of ``transform``."""
    return {
        "header": _header_to_ros(transform.frame_id, transform.stamp, ros2),
        "child_frame_id": transform.child_frame_id,
        "transform": {
            "translation": _vector(transform.translation, "xyz"),
            "rotation": _vector(transform.rotation, "xyzw"),
        },
    }


def transform_stamped_from_ros(d: object) -> TransformStamped:
    """TransformStamped of a ``geometry_msgs/TransformStamped`` dict."""
    frame_id, stamp = _header_from_ros(d)
    child = _get(d, "child_frame_id", "")
    if not isinstance(child, str) or not child:
        raise RosMessageError(
            f"child_frame_id must be a non-empty frame name, got {child!r}", "child_frame_id"
        )
    t = _get(d, "transform", "")
    translation = _xyz(_get(t, "translation", "transform"), "transform.translation")
    rotation = _xyzw(_get(t, "rotation", "transform"), "transform.rotation")
    return TransformStamped(frame_id, child, translation, rotation, stamp)

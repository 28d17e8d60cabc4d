"""ROS 2 message definitions (``.msg`` text, dependencies appended) for the MCAP export.

MCAP's ``ros2msg`` schema encoding stores a type's definition followed by every type it
uses, each after a line of 80 ``=`` and ``MSG: package/Type``.
"""

from __future__ import annotations

_DEFINITIONS: dict[str, str] = {
    "builtin_interfaces/Time": "int32 sec\nuint32 nanosec\n",
    "std_msgs/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
    "geometry_msgs/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/Point": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/Quaternion": "float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n",
    "geometry_msgs/Transform": "Vector3 translation\nQuaternion rotation\n",
    "geometry_msgs/Pose": "Point position\nQuaternion orientation\n",
    "geometry_msgs/TransformStamped": (
        "std_msgs/Header header\nstring child_frame_id\nTransform transform\n"
    ),
    "geometry_msgs/PoseStamped": "std_msgs/Header header\nPose pose\n",
    "tf2_msgs/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
    "sensor_msgs/JointState": (
        "std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\n"
        "float64[] effort\n"
    ),
}

_USES: dict[str, tuple[str, ...]] = {
    "std_msgs/Header": ("builtin_interfaces/Time",),
    "geometry_msgs/Transform": ("geometry_msgs/Vector3", "geometry_msgs/Quaternion"),
    "geometry_msgs/Pose": ("geometry_msgs/Point", "geometry_msgs/Quaternion"),
    "geometry_msgs/TransformStamped": ("std_msgs/Header", "geometry_msgs/Transform"),
    "geometry_msgs/PoseStamped": ("std_msgs/Header", "geometry_msgs/Pose"),
    "tf2_msgs/TFMessage": ("geometry_msgs/TransformStamped",),
    "sensor_msgs/JointState": ("std_msgs/Header",),
}

SEPARATOR = "=" * 80


def _dependencies(name: str) -> list[str]:
    """Every type ``name`` uses, depth first, each once."""
    found: list[str] = []
    for used in _USES.get(name, ()):
        for dep in (used, *_dependencies(used)):
            if dep not in found:
                found.append(dep)
    return found


def message_definition(name: str) -> str:
    """The full ``ros2msg`` schema text of ``name`` (e.g. ``"sensor_msgs/JointState"``)."""
    if name not in _DEFINITIONS:
        raise KeyError(f"no ROS 2 definition for {name!r}; known: {sorted(_DEFINITIONS)}")
    parts = [_DEFINITIONS[name]]
    for dep in _dependencies(name):
        parts.append(f"{SEPARATOR}\nMSG: {dep}\n{_DEFINITIONS[dep]}")
    return "".join(parts)

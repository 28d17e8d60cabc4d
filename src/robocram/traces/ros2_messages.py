"""ROS 2 message definitions (``.msg`` text, dependencies appended) for the MCAP export.

MCAP's ``ros2msg`` schema encoding stores a type's definition followed by every type it
uses, each after a line of 80 ``=`` and ``MSG: package/Type``. Schemas are named as ROS 2
names them (``tf2_msgs/msg/TFMessage``), so Foxglove's panels recognise them; the types
below are ROS 2 Jazzy's (a test reads the installed ``.msg`` files; Humble's have the same
fields).
"""

from __future__ import annotations

from robocram.traces.errors import TraceUnknownKey

_MARKER = """int32 ARROW=0
int32 CUBE=1
int32 SPHERE=2
int32 CYLINDER=3
int32 LINE_STRIP=4
int32 LINE_LIST=5
int32 CUBE_LIST=6
int32 SPHERE_LIST=7
int32 POINTS=8
int32 TEXT_VIEW_FACING=9
int32 MESH_RESOURCE=10
int32 TRIANGLE_LIST=11
int32 ADD=0
int32 MODIFY=0
int32 DELETE=2
int32 DELETEALL=3
std_msgs/Header header
string ns
int32 id
int32 type
int32 action
geometry_msgs/Pose pose
geometry_msgs/Vector3 scale
std_msgs/ColorRGBA color
builtin_interfaces/Duration lifetime
bool frame_locked
geometry_msgs/Point[] points
std_msgs/ColorRGBA[] colors
string texture_resource
sensor_msgs/CompressedImage texture
UVCoordinate[] uv_coordinates
string text
string mesh_resource
MeshFile mesh_file
bool mesh_use_embedded_materials
"""

_DEFINITIONS: dict[str, str] = {
    "builtin_interfaces/msg/Time": "int32 sec\nuint32 nanosec\n",
    "builtin_interfaces/msg/Duration": "int32 sec\nuint32 nanosec\n",
    "std_msgs/msg/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
    "std_msgs/msg/String": "string data\n",
    "std_msgs/msg/ColorRGBA": "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n",
    "geometry_msgs/msg/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/msg/Point": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/msg/Quaternion": "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
    "geometry_msgs/msg/Transform": "Vector3 translation\nQuaternion rotation\n",
    "geometry_msgs/msg/Pose": "Point position\nQuaternion orientation\n",
    "geometry_msgs/msg/TransformStamped": (
        "std_msgs/Header header\nstring child_frame_id\nTransform transform\n"
    ),
    "geometry_msgs/msg/PoseStamped": "std_msgs/Header header\nPose pose\n",
    "tf2_msgs/msg/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
    "sensor_msgs/msg/JointState": (
        "std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\n"
        "float64[] effort\n"
    ),
    "sensor_msgs/msg/CompressedImage": "std_msgs/Header header\nstring format\nuint8[] data\n",
    "visualization_msgs/msg/UVCoordinate": "float32 u\nfloat32 v\n",
    "visualization_msgs/msg/MeshFile": "string filename\nuint8[] data\n",
    "visualization_msgs/msg/Marker": _MARKER,
    "visualization_msgs/msg/MarkerArray": "Marker[] markers\n",
}

_USES: dict[str, tuple[str, ...]] = {
    "std_msgs/msg/Header": ("builtin_interfaces/msg/Time",),
    "geometry_msgs/msg/Transform": ("geometry_msgs/msg/Vector3", "geometry_msgs/msg/Quaternion"),
    "geometry_msgs/msg/Pose": ("geometry_msgs/msg/Point", "geometry_msgs/msg/Quaternion"),
    "geometry_msgs/msg/TransformStamped": ("std_msgs/msg/Header", "geometry_msgs/msg/Transform"),
    "geometry_msgs/msg/PoseStamped": ("std_msgs/msg/Header", "geometry_msgs/msg/Pose"),
    "tf2_msgs/msg/TFMessage": ("geometry_msgs/msg/TransformStamped",),
    "sensor_msgs/msg/JointState": ("std_msgs/msg/Header",),
    "sensor_msgs/msg/CompressedImage": ("std_msgs/msg/Header",),
    "visualization_msgs/msg/Marker": (
        "std_msgs/msg/Header",
        "geometry_msgs/msg/Pose",
        "geometry_msgs/msg/Vector3",
        "std_msgs/msg/ColorRGBA",
        "builtin_interfaces/msg/Duration",
        "geometry_msgs/msg/Point",
        "sensor_msgs/msg/CompressedImage",
        "visualization_msgs/msg/UVCoordinate",
        "visualization_msgs/msg/MeshFile",
    ),
    "visualization_msgs/msg/MarkerArray": ("visualization_msgs/msg/Marker",),
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
    """The full ``ros2msg`` schema text of ``name`` (e.g. ``"sensor_msgs/msg/JointState"``).

    Dependencies are headed ``MSG: package/Type``, as ``ros2 bag`` writes them.
    """
    if name not in _DEFINITIONS:
        raise TraceUnknownKey(f"no ROS 2 definition for {name!r}; known: {sorted(_DEFINITIONS)}")
    parts = [_DEFINITIONS[name]]
    for dep in _dependencies(name):
        package, _, kind = dep.split("/")
        parts.append(f"{SEPARATOR}\nMSG: {package}/{kind}\n{_DEFINITIONS[dep]}")
    return "".join(parts)

"""The MCAP export's ROS 2 message definitions are Jazzy's: every field of every type the
export writes matches the ``.msg`` files of the ROS 2 installed by ``make setup`` (read
from its share folder, not from our code), so ROS 2 tools decode the recording."""

from __future__ import annotations

import re

from robocram.ros.ros2_environment import ros2_prefix
from robocram.traces import ros2_messages
from robocram.traces.ros2_messages import message_definition

# not among the wheels make setup installs; Humble's and Jazzy's have the same fields
NOT_INSTALLED = {
    "visualization_msgs/msg/Marker",
    "visualization_msgs/msg/MarkerArray",
    "visualization_msgs/msg/MeshFile",
    "visualization_msgs/msg/UVCoordinate",
}


def _lines(text: str) -> list[str]:
    """The declarations of a ``.msg`` text: comments and blank lines out, spaces single."""
    found = (re.sub(r"\s+", " ", line.split("#", 1)[0].strip()) for line in text.splitlines())
    return [line for line in found if line]


def test_every_installed_type_is_declared_as_jazzy_declares_it() -> None:
    share = ros2_prefix().root / "share"
    checked, absent = [], set()
    for name, text in sorted(ros2_messages._DEFINITIONS.items()):
        package, _, kind = name.split("/")
        installed = share / package / "msg" / f"{kind}.msg"
        if not installed.exists():
            absent.add(name)
            continue
        assert _lines(text) == _lines(installed.read_text(encoding="utf-8")), name
        checked.append(name)
    assert absent == NOT_INSTALLED
    assert len(checked) == 15  # the transforms, joint states, poses, headers, times, ...


def test_a_schema_holds_each_type_it_uses_once_after_the_type() -> None:
    text = message_definition("tf2_msgs/msg/TFMessage")
    headings = re.findall(r"^MSG: (\S+)$", text, flags=re.MULTILINE)
    assert headings == [
        "geometry_msgs/TransformStamped",
        "std_msgs/Header",
        "builtin_interfaces/Time",
        "geometry_msgs/Transform",
        "geometry_msgs/Vector3",
        "geometry_msgs/Quaternion",
    ]

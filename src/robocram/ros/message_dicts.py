"""ROS 1 messages to and from plain dictionaries, the form our transport passes around.

Dictionaries keep the transport independent of genpy (a ROS 2 or rosbridge transport
speaks the same nested dicts). Times and durations are ``{"secs", "nsecs"}`` both ways,
as rosbridge writes them. Used inside the ROS processes only.
"""

from __future__ import annotations

import importlib
from typing import Any

from robocram.ros.errors import RosArgumentError

RosDict = dict[str, Any]


def message_class(type_name: str) -> Any:
    """The genpy class of ``pkg/Name``, e.g. ``control_msgs/FollowJointTrajectoryGoal``."""
    package, _, name = type_name.partition("/")
    if not name:
        raise RosArgumentError(f"message type {type_name!r} is not of the form package/Name")
    return getattr(importlib.import_module(f"{package}.msg"), name)


def to_message(type_name: str, data: RosDict) -> Any:
    """A new message of ``type_name`` filled from ``data`` (missing fields keep defaults)."""
    import genpy

    message = message_class(type_name)()
    genpy.message.fill_message_args(message, [data])
    return message


def to_dict(message: Any) -> Any:
    """The message as nested dicts, lists and numbers (times as ``{"secs", "nsecs"}``)."""
    import genpy

    if isinstance(message, genpy.TVal):
        return {"secs": message.secs, "nsecs": message.nsecs}
    if isinstance(message, genpy.Message):
        return {slot: to_dict(getattr(message, slot)) for slot in message.__slots__}
    if isinstance(message, list | tuple):
        return [to_dict(item) for item in message]
    return message

"""ROS 2 messages to and from the transport's plain dictionaries (ROS 2 processes only).

The transport speaks one dictionary layout for both ROS versions, rosbridge's: times and
durations are ``{"secs", "nsecs"}``. ROS 2's ``builtin_interfaces`` Time and Duration are
``{"sec", "nanosec"}``, so they are translated here, both ways; a ROS 1 header's ``seq``
(which ROS 2 dropped) is ignored. Any other unknown field is an error naming the fields
the message has. Action types are named as in the facts, ``control_msgs/GripperCommand``.
"""

from __future__ import annotations

import importlib
from typing import Any

from robocram.ros.errors import RosArgumentError, RosUnknownKey
from robocram.ros.transport import RosDict

# rclpy's nodes, clients, goal handles and generated message classes: the wheels ship no
# type information, so these stay untyped, under one name that says why
RclpyObject = Any
TIME_TYPES = ("Time", "Duration")
DROPPED = frozenset({"seq"})  # ROS 1 fields ROS 2 has no more
FLOATS = frozenset({"double", "float"})
INTEGERS = frozenset(
    {"int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64", "octet"}
)


def action_class(type_name: str) -> RclpyObject:
    """The rclpy action class of ``pkg/Name`` (``pkg/action/Name`` also works)."""
    package, _, name = type_name.replace("/action/", "/").partition("/")
    if not name:
        raise RosArgumentError(f"action type {type_name!r} is not of the form package/Name")
    return getattr(importlib.import_module(f"{package}.action"), name)


def message_class(type_name: str) -> RclpyObject:
    """The rclpy message class of ``pkg/Name`` (``pkg/msg/Name`` also works)."""
    package, _, name = type_name.replace("/msg/", "/").partition("/")
    if not name:
        raise RosArgumentError(f"message type {type_name!r} is not of the form package/Name")
    return getattr(importlib.import_module(f"{package}.msg"), name)


def _is_time(message: RclpyObject) -> bool:
    return type(message).__module__.startswith("builtin_interfaces") and (
        type(message).__name__ in TIME_TYPES
    )


def _element_class(slot_type: RclpyObject) -> RclpyObject | None:
    """The message class of a sequence's elements, None for primitives."""
    value_type = getattr(slot_type, "value_type", None)
    namespaces = getattr(value_type, "namespaces", None)
    if value_type is None or not namespaces:
        return None
    return getattr(importlib.import_module(".".join(namespaces)), value_type.name)


def _primitive(kind: str, value: RclpyObject) -> RclpyObject:
    """``value`` as the Python type rclpy's setters demand for a field of ``kind``."""
    base = kind.split("<", 1)[-1].split("[", 1)[0].rstrip(">")
    convert = float if base in FLOATS else int if base in INTEGERS else None
    if convert is None or isinstance(value, str):
        return value
    if isinstance(value, list | tuple):
        return [convert(v) for v in value]
    return convert(value)


def fill(message: RclpyObject, data: RosDict, path: str = "") -> RclpyObject:
    """Set ``message``'s fields from ``data`` (missing fields keep their defaults)."""
    if _is_time(message) and ("secs" in data or "nsecs" in data):
        data = {"sec": data.get("secs", 0), "nanosec": data.get("nsecs", 0)}
    fields = message.get_fields_and_field_types()
    slots = dict(zip(fields, type(message).SLOT_TYPES, strict=True))
    for key, value in data.items():
        if key not in fields:
            if key in DROPPED:
                continue
            raise RosUnknownKey(
                f"{type(message).__name__} has no field {path}{key!r}; it has {sorted(fields)}"
            )
        current = getattr(message, key)
        element = _element_class(slots[key])
        if hasattr(current, "get_fields_and_field_types"):
            fill(current, value, f"{path}{key}.")
        elif element is not None:
            setattr(message, key, [fill(element(), v, f"{path}{key}[].") for v in value])
        else:
            setattr(message, key, _primitive(fields[key], value))
    return message


def to_dict(message: RclpyObject) -> RclpyObject:
    """The message as nested dicts, lists and numbers (times as ``{"secs", "nsecs"}``)."""
    if hasattr(message, "get_fields_and_field_types"):
        if _is_time(message):
            return {"secs": message.sec, "nsecs": message.nanosec}
        return {
            name: to_dict(getattr(message, name)) for name in message.get_fields_and_field_types()
        }
    if hasattr(message, "tolist"):  # numpy arrays and scalars, array.array
        return message.tolist()
    if isinstance(message, list | tuple):
        return [to_dict(item) for item in message]
    return message

"""A ``tf2_msgs/TFMessage`` read from and written to its serialized (CDR) bytes.

A robot publishes hundreds of transforms on ``/tf`` at 30 Hz or more. rclpy turns each
into Python message objects, field by field, holding the interpreter's lock long enough
to delay our node's answers to the plan process; our ROS 2 node subscribes raw instead
and reads the few fields it keeps here (stamps, frames, translation, rotation),
and the projection driver publishes the bytes written here.

Layout (XCDR1, as Fast DDS writes it): a 4-byte encapsulation header whose second byte
is 1 for little-endian, then ``uint32`` count of TransformStamped, each: ``int32 sec``,
``uint32 nanosec``, ``string frame_id``, ``string child_frame_id`` (``uint32`` length
with the terminating NUL, then the bytes), 7 ``float64`` (translation xyz, rotation xyzw)
aligned to 8 bytes; offsets aligned from the end of the encapsulation header.
"""

from __future__ import annotations

import struct
from collections.abc import Iterable

from robocram.ros.errors import RosArgumentError

Transform = tuple[str, str, tuple[float, float, float], tuple[float, float, float, float]]


def _align(offset: int, size: int) -> int:
    return (offset + size - 1) & ~(size - 1)


def read_tf_message(raw: bytes) -> list[Transform]:
    """``(parent, child, translation, rotation)`` of every transform in the message.

    Raises:
        RosArgumentError: the bytes are not a CDR-encoded TFMessage (truncated, bad header).
    """
    return [transform for _, transform in read_stamped_tf_message(raw)]


def read_stamped_tf_message(raw: bytes) -> list[tuple[float, Transform]]:
    """``(stamp [s], (parent, child, translation, rotation))`` of every transform.

    Raises:
        RosArgumentError: the bytes are not a CDR-encoded TFMessage (truncated, bad header).
    """
    if len(raw) < 8:
        raise RosArgumentError(f"a TFMessage needs at least 8 bytes, got {len(raw)}")
    order = "<" if raw[1] == 1 else ">"
    data = memoryview(raw)[4:]
    try:
        (count,) = struct.unpack_from(order + "I", data, 0)
        offset = 4
        transforms: list[tuple[float, Transform]] = []
        for _ in range(count):
            sec, nanosec = struct.unpack_from(order + "iI", data, offset)
            offset += 8  # aligned: every field before is 4-byte
            parent, offset = _string(data, offset, order)
            child, offset = _string(data, _align(offset, 4), order)
            offset = _align(offset, 8)
            x, y, z, qx, qy, qz, qw = struct.unpack_from(order + "7d", data, offset)
            offset += 56
            stamp = sec + nanosec * 1e-9
            transforms.append((stamp, (parent, child, (x, y, z), (qx, qy, qz, qw))))
            offset = _align(offset, 4)
    except struct.error as err:
        raise RosArgumentError(f"not a CDR TFMessage: {err}") from err
    return transforms


def write_tf_message(stamp: tuple[int, int], transforms: Iterable[Transform]) -> bytes:
    """The little-endian CDR bytes of a TFMessage of ``transforms``, all stamped
    ``stamp`` (sec, nanosec); rclpy publishes them as they are (``publish(bytes)``)."""
    out = bytearray(b"\x00\x01\x00\x00\x00\x00\x00\x00")  # header, count (set below)
    count = 0
    for parent, child, translation, rotation in transforms:
        _pad(out, 4)
        out += struct.pack("<iI", *stamp)
        _put_string(out, parent)
        _pad(out, 4)
        _put_string(out, child)
        _pad(out, 8)
        out += struct.pack("<7d", *translation, *rotation)
        count += 1
    struct.pack_into("<I", out, 4, count)
    return bytes(out)


def _pad(out: bytearray, size: int) -> None:
    """Zero bytes that align the end of ``out`` (counted from the header's end) to ``size``."""
    offset = len(out) - 4
    out += bytes(_align(offset, size) - offset)


def _put_string(out: bytearray, text: str) -> None:
    encoded = text.encode() + b"\x00"
    out += struct.pack("<I", len(encoded)) + encoded


def _string(data: memoryview, offset: int, order: str) -> tuple[str, int]:
    (length,) = struct.unpack_from(order + "I", data, offset)
    start = offset + 4
    end = start + length
    if end > len(data) or length == 0:
        raise struct.error(f"a string of {length} bytes at {offset} runs past the message")
    return bytes(data[start : end - 1]).decode(), end

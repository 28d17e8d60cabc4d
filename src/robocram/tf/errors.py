"""Errors of the frames layer: one root, :class:`TfError`, with data-carrying subclasses."""

from __future__ import annotations

import difflib
from collections.abc import Iterable


class TfError(Exception):
    """Root of every error raised by :mod:`robocram.tf`."""


class TransformError(TfError):
    """A frame is unknown, unconnected or would close a cycle in the transform tree.

    Attributes:
        frame: the culprit frame name.
        known_frames: the frames the tree knew when the error was raised.
    """

    def __init__(self, message: str, frame: str, known_frames: Iterable[str] = ()) -> None:
        super().__init__(message)
        self.frame = frame
        self.known_frames = tuple(sorted(known_frames))


class RosMessageError(TfError, ValueError):
    """A ROS JSON-bridge dictionary lacks a key or holds a value of the wrong kind.

    Attributes:
        path: dotted path of the culprit key, e.g. ``"pose.orientation.w"``.
    """

    def __init__(self, message: str, path: str) -> None:
        super().__init__(message)
        self.path = path


class PoseValueError(TfError, ValueError):
    """A position, orientation or pose given with values no pose has: the wrong count of
    components, a component that is not finite, a quaternion of no length. Always the
    giver's mistake: a process module reports it as its caller's, not as its own bug."""


def closest_names(name: str, candidates: Iterable[str], n: int = 3) -> list[str]:
    """Return up to ``n`` names of ``candidates`` that look like ``name`` (for "did you mean")."""
    pool = list(candidates)
    close = difflib.get_close_matches(name, pool, n=n, cutoff=0.5)
    if close:
        return close
    return [c for c in pool if name in c or c in name][:n]


def unknown_frame(frame: str, known: Iterable[str], what: str = "frame") -> TransformError:
    """Build the :class:`TransformError` for an unknown ``frame``, suggesting close names."""
    known = tuple(known)
    close = closest_names(frame, known)
    hint = f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""
    if not known:
        hint = "; the transform tree is empty: feed it with set_transform or update_from"
    return TransformError(f"unknown {what} {frame!r}{hint}", frame, known)


class TfArgumentError(TfError, ValueError):
    """A value given to the transform layer is outside what it accepts."""

    summary = "a value given to the transform layer is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"


class TfUsageError(TfError, TypeError):
    """The transform layer was handed the wrong kind of thing: the caller's mistake."""

    summary = "the transform layer was handed the wrong kind of thing"
    hint = "pass what the message asks for"

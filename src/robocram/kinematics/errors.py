"""Errors of the kinematics layer: one root, :class:`KinematicsError`.

An unreachable target is no error: :func:`~robocram.kinematics.solve_ik` reports it with
``IKResult.success == False`` so that plans can raise their own failure from it.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable


class KinematicsError(Exception):
    """Root of every error raised by :mod:`robocram.kinematics`."""


class UnknownNameError(KinematicsError, KeyError):
    """An arm, joint or frame name the robot does not have.

    Attributes:
        kind: "arm", "joint" or "frame".
        name: the culprit name.
        robot: the robot's name.
        suggestions: the closest existing names.
    """

    def __init__(self, kind: str, name: str, robot_name: str, known: Iterable[str]) -> None:
        pool = list(known)
        close = difflib.get_close_matches(name, pool, n=3, cutoff=0.5)
        if not close:
            close = sorted((c for c in pool if name and name in c), key=len)[:3]
        self.kind = kind
        self.name = name
        self.robot = robot_name
        self.suggestions = tuple(close)
        hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
        if not close and len(pool) <= 8:
            hint = f"; known {kind}s: {', '.join(repr(p) for p in sorted(pool)) or 'none'}"
        super().__init__(f"{kind} {name!r} not in {robot_name}{hint}")

    def __str__(self) -> str:
        return str(self.args[0])


class TargetFrameError(KinematicsError):
    """A target pose is given in a frame that is not part of the robot."""

    def __init__(self, frame: str, robot_name: str, root: str) -> None:
        self.frame = frame
        self.robot = robot_name
        self.root = root
        super().__init__(
            f"target frame {frame!r} is no frame of {robot_name}; transform the target into "
            f"{root!r} first (robocram.tf.transform_pose(target, {root!r}))"
        )


class KinematicsArgumentError(KinematicsError, ValueError):
    """A value given to the kinematics is outside what it accepts."""

    summary = "a value given to the kinematics is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"


class KinematicsUsageError(KinematicsError, TypeError):
    """The kinematics was handed the wrong kind of thing: the caller's mistake."""

    summary = "the kinematics was handed the wrong kind of thing"
    hint = "pass what the message asks for"

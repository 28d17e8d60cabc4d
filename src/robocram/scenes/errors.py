"""The scenes' exceptions: one root, each naming the robot and what it lacks."""

from __future__ import annotations


class SceneError(Exception):
    """Root of every error raised by :mod:`robocram.scenes`."""


class UnfitRobotError(SceneError):
    """The robot's description lacks what the scene needs (a gripper arm, enough reach)."""

    def __init__(self, robot_name: str, why: str) -> None:
        self.robot = robot_name
        self.why = why
        super().__init__(f"cannot build the scene for {robot_name!r}: {why}")


class SceneArgumentError(SceneError, ValueError):
    """A value given to a scene is outside what it accepts."""

    summary = "a value given to a scene is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"

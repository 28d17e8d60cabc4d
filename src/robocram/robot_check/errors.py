"""The robot checker's errors: a description it cannot find or import."""

from __future__ import annotations

from robocram.robots import DescriptionError


class RobotCheckError(DescriptionError):
    """The description to check cannot be found or built; the message says how to name it."""


class CheckUnknownKey(RobotCheckError, KeyError):
    """A name that a robot check does not know; the message lists the known ones."""

    summary = "a name that a robot check does not know"
    hint = "use one of the names the message lists"

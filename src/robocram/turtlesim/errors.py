"""Errors of :mod:`robocram.turtlesim`: one root, and the kinds of wrong input it refuses."""

from __future__ import annotations


class TurtleError(Exception):
    """Root of the errors of :mod:`robocram.turtlesim` that are not plan failures."""


class TurtleArgumentError(TurtleError, ValueError):
    """A value given to the turtle simulation is outside what it accepts."""

    summary = "a value given to the turtle simulation is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"

"""Errors of :mod:`robocram.ros_driver`: one root, and the kinds of wrong input it refuses."""

from __future__ import annotations


class DriverError(Exception):
    """Root of the errors of :mod:`robocram.ros_driver` that are not plan failures."""


class DriverArgumentError(DriverError, ValueError):
    """A value given to the projection driver is outside what it accepts."""

    summary = "a value given to the projection driver is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"

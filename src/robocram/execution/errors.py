"""Errors of :mod:`robocram.execution`: one root, and the kinds of wrong input it refuses."""

from __future__ import annotations


class ExecutionError(Exception):
    """Root of the errors of :mod:`robocram.execution` that are not plan failures."""


class ExecutionArgumentError(ExecutionError, ValueError):
    """A value given to the plan language is outside what it accepts."""

    summary = "a value given to the plan language is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"


class ExecutionUsageError(ExecutionError, TypeError):
    """The plan language was handed the wrong kind of thing: the caller's mistake."""

    summary = "the plan language was handed the wrong kind of thing"
    hint = "pass what the message asks for"


class ExecutionUnknownKey(ExecutionError, KeyError):
    """A name that the plan language does not know; the message lists the known ones."""

    summary = "a name that the plan language does not know"
    hint = "use one of the names the message lists"


class ExecutionStateError(ExecutionError, RuntimeError):
    """The plan language was used out of order; the message says what must happen first."""

    summary = "the plan language was used out of order"
    hint = "the message says what must happen first"

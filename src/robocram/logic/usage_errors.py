"""Misuse of the engine's Python API (a bad limit, a non-callable predicate): typed, with a
summary and a hint, and apart from :mod:`errors` so the term modules can raise them
without an import cycle. Prolog's own errors are :class:`~robocram.logic.errors.PrologError`."""

from __future__ import annotations


class LogicError(Exception):
    """Root of misuse of robocram.logic's Python API (Prolog's own errors are PrologError)."""


class LogicArgumentError(LogicError, ValueError):
    """A value given to the Prolog engine's Python side is outside what it accepts."""

    summary = "a value given to the Prolog engine's Python side is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"


class LogicUsageError(LogicError, TypeError):
    """The Prolog engine's Python side was handed the wrong kind of thing: the caller's mistake."""

    summary = "the Prolog engine's Python side was handed the wrong kind of thing"
    hint = "pass what the message asks for"

"""Errors of the designators layer: one root, :class:`DesignatorError`, with data-carrying kinds.

The execution layer turns a :class:`DesignatorError` met during PERFORM into its
``DesignatorReferenceFailure``; here the errors only say which designator failed and why.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Protocol


class Described(Protocol):
    """What an error needs of its culprit designator (designator.py imports this module)."""

    @property
    def description(self) -> str:
        """The designator written the CRAM way."""


class DesignatorError(Exception):
    """Root of every error raised by :mod:`robocram.designators`.

    Attributes:
        designator: the culprit designator (or None when the error is about a property).
    """

    def __init__(self, message: str, designator: Described | None = None) -> None:
        super().__init__(message)
        self.designator = designator


class DesignatorPropertyError(DesignatorError, ValueError):
    """A designator was written with a malformed property (bad key, missing type...).

    Attributes:
        key: the culprit property key.
    """

    def __init__(self, message: str, key: str, designator: Described | None = None) -> None:
        super().__init__(message, designator)
        self.key = key


class GroundingError(DesignatorError):
    """A designator has no (more) solution: no grounding rule, no pose, no perceived data.

    Attributes:
        grounded_types: the ``type`` values that do have grounding rules for this kind,
            when the knowledge base could tell (empty otherwise).
    """

    def __init__(
        self,
        message: str,
        designator: Described | None = None,
        grounded_types: Iterable[str] = (),
    ) -> None:
        super().__init__(message, designator)
        self.grounded_types = tuple(sorted(set(grounded_types)))


class MotionPropertyError(DesignatorPropertyError, GroundingError):
    """A motion designator lacks a property its type needs, or has one of the wrong type.

    Attributes:
        motion: the motion ``type`` (``moving-tcp``).
        key: the culprit property key.
        expected: the accepted values in words.
    """

    def __init__(
        self,
        message: str,
        motion: str,
        key: str,
        expected: str,
        designator: Described | None = None,
        grounded_types: Iterable[str] = (),
    ) -> None:
        DesignatorError.__init__(self, message, designator)
        self.key = key
        self.grounded_types = tuple(sorted(set(grounded_types)))
        self.motion = motion
        self.expected = expected


class DesignatorArgumentError(DesignatorError, ValueError):
    """A value given to a designator is outside what it accepts."""

    summary = "a value given to a designator is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"


class DesignatorUsageError(DesignatorError, TypeError):
    """A designator was handed the wrong kind of thing: the caller's mistake."""

    summary = "a designator was handed the wrong kind of thing"
    hint = "pass what the message asks for"


class DesignatorUnknownKey(DesignatorError, KeyError):
    """A name that a designator does not know; the message lists the known ones."""

    summary = "a name that a designator does not know"
    hint = "use one of the names the message lists"

"""Errors of the projection layer that are programming mistakes, not plan failures.

A bad arm name or an unknown frame is the caller's bug, so it raises
:class:`ProjectionError` (a ``SetupFailure``, so still a plan failure, and a
``ValueError``) with the culprit named and a fix suggested; a goal the robot cannot
achieve raises a typed plan failure from ``robocram.execution.failures``.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable

from robocram.execution.failures import SetupFailure


class ProjectionError(SetupFailure, ValueError):
    """Root of the projection layer's input errors."""


def unknown_name(kind: str, name: object, owner: str, known: Iterable[str]) -> ProjectionError:
    """An error for ``name`` not being one of ``known``, with the closest names suggested."""
    pool = sorted(known)
    close = difflib.get_close_matches(str(name), pool, n=3, cutoff=0.5)
    if close:
        hint = f"; did you mean {' or '.join(repr(c) for c in close)}?"
    elif len(pool) <= 10:
        hint = f"; known {kind}s: {', '.join(repr(p) for p in pool) or 'none'}"
    else:
        hint = f"; {owner} has {len(pool)} {kind}s"
    return ProjectionError(f"{kind} {name!r} not in {owner}{hint}")


class ProjectionUsageError(TypeError):
    """Projection was handed the wrong kind of thing: the caller's mistake."""

    summary = "projection was handed the wrong kind of thing"
    hint = "pass what the message asks for"

"""Designator properties: an ordered tuple of ``(key, value)`` pairs where keys may repeat.

Written the CRAM way as keyword arguments (``type="looking", target=loc``); a property
given as None is left out (CRAM's ``desig:when``), and a property that repeats is given
as positional ``(key, value)`` pairs before the keywords.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from robocram.designators.errors import DesignatorPropertyError

PropertyPair = tuple[str, Any]


def normalize_properties(
    pairs: Sequence[PropertyPair], keywords: Mapping[str, Any]
) -> tuple[PropertyPair, ...]:
    """Return the properties as a tuple of pairs, positional pairs first, None values dropped.

    >>> normalize_properties([("near", "sink"), ("near", "oven")], {"on": None, "type": "cup"})
    (('near', 'sink'), ('near', 'oven'), ('type', 'cup'))
    """
    out: list[PropertyPair] = []
    for pair in pairs:
        if not (isinstance(pair, tuple) and len(pair) == 2):
            raise DesignatorPropertyError(
                f"positional designator property {pair!r} is not a (key, value) pair; "
                "write repeated properties as ('near', x), ('near', y) and others as key=value",
                key=str(pair),
            )
        out.append(_checked(pair[0], pair[1]))
    out.extend(_checked(key, value) for key, value in keywords.items())
    return tuple(pair for pair in out if pair[1] is not None)


def _checked(key: object, value: object) -> PropertyPair:
    if not isinstance(key, str) or not key.isidentifier():
        raise DesignatorPropertyError(
            f"designator property key {key!r} is not an identifier; "
            "use snake_case names such as 'joint_angle' (CRAM's :joint-angle)",
            key=str(key),
        )
    return key, value


def format_value(value: object) -> str:
    """Render a property value for a designator's description (designators render nested)."""
    description = getattr(value, "description", None)
    if isinstance(description, str):
        return description
    if isinstance(value, str):
        return value
    return repr(value)

"""Designator property values as JSON: poses, designators and terms in a readable form."""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from typing import Any

from robocram.designators import Designator
from robocram.tf import Pose, PoseStamped

_MAX_TEXT = 400  # [characters] of a repr kept for values without a JSON form


def json_value(value: Any) -> Any:
    """A JSON-able form of ``value``: numbers, strings, lists, dicts; poses and designators
    as dicts; anything else as its (shortened) repr."""
    if value is None or isinstance(value, bool | int | str):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else str(value)
    if isinstance(value, Designator):
        return {"designator": value.description}
    if isinstance(value, PoseStamped):
        return {
            "frame": value.frame_id,
            "position": list(value.position),
            "orientation": list(value.orientation),
        }
    if isinstance(value, Pose):
        return {"position": list(value.position), "orientation": list(value.orientation)}
    if isinstance(value, list | tuple):
        return [json_value(v) for v in value]
    if isinstance(value, Mapping):
        return {str(k): json_value(v) for k, v in value.items()}
    return repr(value)[:_MAX_TEXT]


def dumps(value: Any) -> str:
    """``value`` as compact JSON text (see :func:`json_value`)."""
    return json.dumps(json_value(value), separators=(",", ":"))

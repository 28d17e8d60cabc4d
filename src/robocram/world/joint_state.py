"""Joint values by name: limits enforced (and reported), mimic joints following."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from robocram.world.errors import WorldValueError


@dataclass(frozen=True)
class ClampedJoint:
    """A requested joint value outside the limits and the value applied instead."""

    name: str
    requested: float  # [rad | m]
    applied: float  # [rad | m]
    lower: float
    upper: float


@dataclass(frozen=True)
class JointLimits:
    """Position limits [rad | m]; continuous joints have -inf/inf."""

    lower: float
    upper: float

    def clamp(self, value: float) -> float:
        """``value`` moved into ``[lower, upper]``."""
        return min(max(value, self.lower), self.upper)


def clamp_values(
    values: Mapping[str, float], limits: Mapping[str, JointLimits]
) -> tuple[dict[str, float], list[ClampedJoint]]:
    """Clamp each value to its joint's limits; report the ones that moved."""
    applied: dict[str, float] = {}
    clamped: list[ClampedJoint] = []
    for name, raw in values.items():
        value = float(raw)
        if not math.isfinite(value):
            raise WorldValueError(f"joint {name!r}: value {raw!r} is not a finite number")
        lim = limits[name]
        applied[name] = lim.clamp(value)
        if applied[name] != value:
            clamped.append(ClampedJoint(name, value, applied[name], lim.lower, lim.upper))
    return applied, clamped

"""A variant: one way to run a plan, as plain frozen data that pickles to any worker.

It names the robot, moves objects of the scene (shifts from where the scene put them, plus
a seeded random jitter), passes keyword parameters to the plan and carries the seed that
makes the run repeatable wherever it runs.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

from robocram.batch.errors import BadVariant

Vector3 = tuple[float, float, float]


@dataclass(frozen=True)
class Variant:
    """One run of a plan: robot, object shifts [m], plan parameters and a seed.

    Mappings given for ``object_shifts`` and ``parameters`` are stored as sorted tuples,
    so a variant stays hashable and compares by value.
    """

    name: str
    robot: str | None = None  # None: the batch's robot
    object_shifts: tuple[tuple[str, Vector3], ...] = ()  # object -> [m] from its scene pose
    jitter: float = 0.0  # [m] std of a seeded random xy shift added to each shifted object
    parameters: tuple[tuple[str, object], ...] = ()  # keyword arguments of the plan
    look_at: str | None = None  # the plan looks at this object (None: the scene's target)
    seed: int = 0
    tags: tuple[str, ...] = field(default=())

    def __post_init__(self) -> None:
        object.__setattr__(self, "object_shifts", _shifts(self.object_shifts))
        object.__setattr__(self, "parameters", _parameters(self.parameters))
        if not (math.isfinite(self.jitter) and self.jitter >= 0.0):
            raise BadVariant("jitter", self.jitter, "give a finite standard deviation >= 0 [m]")
        if not isinstance(self.seed, int) or isinstance(self.seed, bool) or self.seed < 0:
            raise BadVariant("seed", self.seed, "give an integer >= 0")

    def parameter_dict(self) -> dict[str, object]:
        """The plan's keyword arguments."""
        return dict(self.parameters)


def _shifts(
    value: Mapping[str, Iterable[float]] | Iterable[tuple[str, Iterable[float]]],
) -> tuple[tuple[str, Vector3], ...]:
    items = value.items() if isinstance(value, Mapping) else value
    out: dict[str, Vector3] = {}
    for name, shift in items:
        v = tuple(float(c) for c in shift)
        if len(v) != 3 or not all(math.isfinite(c) for c in v):
            raise BadVariant(f"object_shifts[{name!r}]", shift, "give a finite (dx, dy, dz) [m]")
        out[str(name)] = (v[0], v[1], v[2])
    return tuple(sorted(out.items()))


def _parameters(
    value: Mapping[str, object] | Iterable[tuple[str, object]],
) -> tuple[tuple[str, object], ...]:
    items = list(value.items() if isinstance(value, Mapping) else value)
    for key, _ in items:
        if not (isinstance(key, str) and key.isidentifier()):
            raise BadVariant("parameters", key, "plan parameters are keyword names")
    return tuple(sorted(items, key=lambda kv: kv[0]))

"""A variant: one way to run a plan, as plain frozen data that pickles to any worker.

It names the robot, moves objects of the scene (shifts from where the scene put them, or
absolute poses, plus a seeded random jitter), passes keyword parameters to the plan and
carries the seed that makes the run repeatable wherever it runs.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, fields
from typing import Any

from robocram.batch.errors import BadVariant
from robocram.batch.object_placement import Pose7, Shift, coerce_poses, coerce_shifts

MAX_SEED = 2**32 - 1  # the largest seed numpy's legacy seeding and random take


@dataclass(frozen=True)
class Variant:
    """One run of a plan: robot, object placements, plan parameters and a seed.

    ``object_shifts`` move objects from the scene's poses (``(dx, dy, dz[, dyaw])`` [m, rad]);
    ``object_poses`` put them at absolute poses in ``map`` (``(x, y, z, yaw)`` or a full
    pose, see :mod:`robocram.batch.object_placement`). Mappings are stored as sorted
    tuples, so a variant stays hashable and compares by value.
    """

    name: str
    robot: str | None = None  # None: the batch's robot
    object_shifts: tuple[tuple[str, Shift], ...] = ()  # object -> from its scene pose
    object_poses: tuple[tuple[str, Pose7], ...] = ()  # object -> its pose in map
    jitter: float = 0.0  # [m] std of a seeded random xy shift added to each moved object
    parameters: tuple[tuple[str, object], ...] = ()  # keyword arguments of the plan
    look_at: str | None = None  # the plan looks at this object (None: the scene's target)
    seed: int = 0
    tags: tuple[str, ...] = field(default=())

    def __post_init__(self) -> None:
        _check_names(self)
        object.__setattr__(self, "object_shifts", coerce_shifts(self.object_shifts))
        object.__setattr__(self, "object_poses", coerce_poses(self.object_poses))
        both = {n for n, _ in self.object_shifts} & {n for n, _ in self.object_poses}
        if both:
            raise BadVariant("object_poses", sorted(both), "shift an object or pose it, not both")
        object.__setattr__(self, "parameters", _parameters(self.parameters))
        jitter = self.jitter
        if not (isinstance(jitter, int | float) and math.isfinite(jitter) and jitter >= 0.0):
            raise BadVariant("jitter", jitter, "give a finite standard deviation >= 0 [m]")
        seed = self.seed
        if not isinstance(seed, int) or isinstance(seed, bool) or not 0 <= seed <= MAX_SEED:
            raise BadVariant("seed", seed, f"give an integer in 0..{MAX_SEED} (2**32-1)")

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any]) -> Variant:
        """Build a variant from plain data (a spec file's entry), naming any unknown key."""
        if not isinstance(data, Mapping):
            raise BadVariant("variant", data, f"give a mapping with keys {', '.join(KEYS)}")
        for key in data:
            if key not in KEYS:
                raise BadVariant(str(key), data[key], f"not a variant key; use {', '.join(KEYS)}")
        if "name" not in data:
            raise BadVariant("name", None, "every variant needs a name")
        values = dict(data)
        if "tags" in values and isinstance(values["tags"], list):
            values["tags"] = tuple(values["tags"])
        return cls(**values)

    def parameter_dict(self) -> dict[str, object]:
        """The plan's keyword arguments."""
        return dict(self.parameters)


KEYS = tuple(f.name for f in fields(Variant))


def _check_names(variant: Variant) -> None:
    if not isinstance(variant.name, str):
        raise BadVariant("name", variant.name, "give the variant's name as a string")
    for key in ("robot", "look_at"):
        value = getattr(variant, key)
        if value is not None and not (isinstance(value, str) and value):
            raise BadVariant(key, value, "give a name (a non-empty string) or leave it out")
    tags = variant.tags
    if not (isinstance(tags, tuple) and all(isinstance(t, str) for t in tags)):
        raise BadVariant("tags", tags, "give a tuple of strings")


def _parameters(
    value: Mapping[str, object] | Iterable[tuple[str, object]],
) -> tuple[tuple[str, object], ...]:
    if isinstance(value, str | bytes) or not isinstance(value, Mapping | Iterable):
        raise BadVariant("parameters", value, "give a mapping of keyword name -> value")
    items = list(value.items() if isinstance(value, Mapping) else value)
    for item in items:
        if not (isinstance(item, tuple) and len(item) == 2):
            raise BadVariant("parameters", item, "give a mapping of keyword name -> value")
        if not (isinstance(item[0], str) and item[0].isidentifier()):
            raise BadVariant("parameters", item[0], "plan parameters are keyword names")
    return tuple(sorted(items, key=lambda kv: kv[0]))

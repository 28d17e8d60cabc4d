"""Variants drawn from a spec's ranges one at a time, as the workers ask for them.

``variants: 1000000`` must not draw a million placements before the first one runs, so
:class:`DrawnVariants` is a sized sequence that draws on iteration, in the same order and
with the same values every time (one generator from ``seed``, variant ``i`` is the
``i``-th draw). Indexing draws up to the index; workers only iterate.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import overload

import numpy as np

from robocram.batch.object_placement import coerce_poses, coerce_shifts
from robocram.batch.variant import Variant

Axis = float | tuple[float, float]
Ranges = Mapping[str, tuple[str, Mapping[str, Axis]]]  # object -> (frame, axis -> range)


@dataclass(frozen=True, eq=False)
class DrawnVariants(Sequence[Variant]):
    """``size`` variants placed from ``ranges``, seeded ``seed``, ``seed + 1``, ..."""

    size: int
    seed: int
    ranges: Ranges
    common: Mapping[str, object]  # look_at, parameters, jitter of every variant

    def __len__(self) -> int:
        return self.size

    def __iter__(self) -> Iterator[Variant]:
        rng = np.random.default_rng(self.seed)
        for i in range(self.size):
            yield self._draw(rng, i)

    @overload
    def __getitem__(self, index: int) -> Variant: ...

    @overload
    def __getitem__(self, index: slice) -> tuple[Variant, ...]: ...

    def __getitem__(self, index: int | slice) -> Variant | tuple[Variant, ...]:
        if isinstance(index, slice):
            return tuple(self[i] for i in range(*index.indices(self.size)))
        if not -self.size <= index < self.size:
            raise IndexError(f"variant {index} of {self.size}")
        index %= self.size
        return next(itertools.islice(iter(self), index, None))

    def __eq__(self, other: object) -> bool:
        if isinstance(other, DrawnVariants | tuple | list):
            return len(self) == len(other) and all(a == b for a, b in zip(self, other, strict=True))
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]

    def _draw(self, rng: np.random.Generator, i: int) -> Variant:
        shifts: dict[str, tuple[float, ...]] = {}
        poses: dict[str, tuple[float, ...]] = {}
        for name, (frame, axes) in self.ranges.items():
            values = tuple(_draw(rng, axes.get(a, 0.0)) for a in ("x", "y", "z", "yaw"))
            (poses if frame == "map" else shifts)[name] = values
        return Variant(
            f"v{i:03d}",
            object_shifts=coerce_shifts(shifts),
            object_poses=coerce_poses(poses),
            seed=self.seed + i,
            **self.common,  # type: ignore[arg-type]
        )


def _draw(rng: np.random.Generator, axis: Axis) -> float:
    return axis if isinstance(axis, float) else float(rng.uniform(axis[0], axis[1]))

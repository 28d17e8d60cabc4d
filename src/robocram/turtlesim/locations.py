"""Location designators on the turtle's field: cells of a 3 x 3 grid, kept inside the field.

``a.location(horizontal_position="right", vertical_position="top")`` resolves to random
points ``(x, y, 0)`` in the top right cell, with the tutorial's generator and validator.
"""

from __future__ import annotations

import random
from collections.abc import Iterator
from typing import Any

from robocram.designators import LocationResolver, Verdict
from robocram.turtlesim.errors import TurtleArgumentError

HORIZONTAL = ("left", "center", "right")
VERTICAL = ("bottom", "center", "top")


def grid_cell_generator(size: float, rng: random.Random) -> Any:
    """Return a generator function of random points in the designator's grid cell.

    It understands ``horizontal_position`` (left/center/right) and ``vertical_position``
    (bottom/center/top) and yields nothing for designators without them.
    """
    cell = size / 3

    def generate(designator: Any) -> Iterator[tuple[float, float, float]]:
        horizontal = designator.get("horizontal_position")
        vertical = designator.get("vertical_position")
        if horizontal is None and vertical is None:
            return
        column = _index(horizontal, HORIZONTAL, "horizontal_position")
        row = _index(vertical, VERTICAL, "vertical_position")
        while True:
            yield (
                rng.uniform(column * cell, (column + 1) * cell),
                rng.uniform(row * cell, (row + 1) * cell),
                0.0,
            )

    return generate


def _index(value: object, names: tuple[str, ...], key: str) -> int:
    if value is None:
        return 1
    if value not in names:
        raise TurtleArgumentError(f"{key} must be one of {names}, got {value!r}")
    return names.index(value)


def field_validator(size: float) -> Any:
    """Return a validator that rejects points off the ``[0, size]^2`` field."""

    def validate(designator: object, candidate: object) -> Verdict:
        position = getattr(candidate, "position", candidate)
        if not isinstance(position, (tuple, list)) or len(position) < 2:
            return Verdict.UNKNOWN
        x, y = position[0], position[1]
        inside = 0.0 <= x <= size and 0.0 <= y <= size
        return Verdict.ACCEPT if inside else Verdict.REJECT

    return validate


def turtle_location_resolver(size: float, seed: int | None = None) -> LocationResolver:
    """Return the default resolver plus the grid cell generator and the field validator."""
    rng = random.Random(seed)
    return (
        LocationResolver()
        .with_generator("grid_cell", grid_cell_generator(size, rng), priority=10)
        .with_validator("field_bounds", field_validator(size))
    )

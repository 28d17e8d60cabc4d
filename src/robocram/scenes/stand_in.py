"""A box standing in for a link whose mesh file is not there.

URDFs taken out of a ROS workspace name meshes under ``package://`` that cannot be found,
so their links would be frames without a shape: a drawer without a floor, a table without
a top. A :class:`StandIn` gives such a link the shape plans need, as robots' missing
meshes stand in as boxes: a solid box (a counter top), an open box (a drawer: a floor
and four low walls, open at the link's +z) or a table (a top on four legs, so a robot's
base can go under its edge). Sizes and centre are in the link's frame; ``robocram env
draft`` guesses them from what the URDF tells, and says so.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from robocram.scenes.errors import SceneArgumentError
from robocram.tf import Vector3

StandInKind = Literal["box", "open_box", "table"]
WALL = 0.01  # [m] an open box's floor and walls are this thick
TABLE_TOP = 0.04  # [m] a table's top is this thick
LEG = 0.05  # [m] a table's legs are this square, at its corners


@dataclass(frozen=True)
class StandIn:
    """A ``kind`` shape of ``size`` [m] centred at ``centre`` [m] in ``link``'s frame."""

    link: str
    kind: StandInKind
    size: Vector3  # [m] along the link's x, y, z
    centre: Vector3 = (0.0, 0.0, 0.0)  # [m]

    def __post_init__(self) -> None:
        if min(self.size) <= 0.0:
            raise SceneArgumentError(
                f"stand-in of {self.link!r}: size {self.size} must be positive"
            )
        if self.kind == "open_box" and min(self.size) <= 2 * WALL:
            raise SceneArgumentError(f"open stand-in of {self.link!r}: {self.size} leaves no room")
        if self.kind == "table" and (min(self.size[:2]) <= 2 * LEG or self.size[2] <= TABLE_TOP):
            raise SceneArgumentError(f"table stand-in of {self.link!r}: {self.size} leaves no legs")

    def boxes(self) -> tuple[tuple[Vector3, Vector3], ...]:
        """``(centre, size)`` of each box making the shape, in the link's frame."""
        if self.kind == "box":
            return ((self.centre, self.size),)
        cx, cy, cz = self.centre
        sx, sy, sz = self.size
        if self.kind == "table":
            leg_z, leg_height = cz - TABLE_TOP / 2, sz - TABLE_TOP
            legs = tuple(
                ((cx + i * (sx - LEG) / 2, cy + j * (sy - LEG) / 2, leg_z), (LEG, LEG, leg_height))
                for i in (-1, 1)
                for j in (-1, 1)
            )
            return (((cx, cy, cz + (sz - TABLE_TOP) / 2), (sx, sy, TABLE_TOP)), *legs)
        wall_z = cz + WALL / 2
        return (
            ((cx, cy, cz - sz / 2 + WALL / 2), (sx, sy, WALL)),  # the floor
            ((cx + (sx - WALL) / 2, cy, wall_z), (WALL, sy, sz - WALL)),
            ((cx - (sx - WALL) / 2, cy, wall_z), (WALL, sy, sz - WALL)),
            ((cx, cy + (sy - WALL) / 2, wall_z), (sx - 2 * WALL, WALL, sz - WALL)),
            ((cx, cy - (sy - WALL) / 2, wall_z), (sx - 2 * WALL, WALL, sz - WALL)),
        )
